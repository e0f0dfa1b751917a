#!/usr/bin/env python3
"""Communication volume of the partition against mesh size and NP (bin/dynx-part only, no MPI).
For cubes of n^3 hex8 elements (scripts/gen_box_deck.py) and NP = 2..64, reads the partition
report: shared nodes per rank (the nodes a rank exchanges each cycle; 3 doubles each for the
force). Model: NP near-cubes cut by planes, mean shared nodes per rank
    a * 6 (NP^(1/3) - 1)/NP * N^(2/3),
with a fitted (geometric mean of measured/ideal) for METIS's jagged cuts; the table gives
measured, model and relative error, and the model's extrapolation to NP = 256 for 1e5 and 1e6
elements. Prints a markdown section (append it to docs/performance.md).
Usage: partition_study.py [outdir]"""
import math, os, re, subprocess, sys

out = sys.argv[1] if len(sys.argv) > 1 else 'build/partition_study'
os.makedirs(out, exist_ok=True)
rows = []
for n in (20, 30, 40, 50):
    deck = os.path.join(out, 'box%d.k' % n)
    subprocess.run([sys.executable, 'scripts/gen_box_deck.py', deck, str(n), str(n), str(n)],
                   check=True)
    for np_ in (2, 4, 8, 16, 32, 64):
        d = os.path.join(out, 'box%d_np%d' % (n, np_))
        subprocess.run(['bin/dynx-part', deck, '-n', str(np_), '-o', d], check=True,
                       stdout=subprocess.DEVNULL)
        shared, bal = [], None
        for line in open(os.path.join(d, 'partition.txt')):
            m = re.match(r'\s*(\d+)\s+(\d+)\s+(\d+)\s+(\d+)\s+(\d+)\s+(\d+)\s*$', line)
            if m:
                shared.append(int(m.group(5)))
            m = re.match(r'balance .*:\s*([0-9.]+)', line)
            if m:
                bal = float(m.group(1))
        for f in os.listdir(d):
            if f.endswith('.h5'):
                os.remove(os.path.join(d, f))
        rows.append((n ** 3, np_, max(shared), sum(shared) / len(shared), bal))
    os.remove(deck)
# model: NP near-cubes of a cube of side L = N^(1/3) cut by NP^(1/3) - 1 planes per direction;
# the cut surface is 3 (NP^(1/3) - 1) L^2, each cut node is shared by the two sides, so the
# mean shared nodes per rank is 6 (NP^(1/3) - 1)/NP N^(2/3), times a fitted factor a for the
# jagged METIS cuts (a = 1 for planar cuts)
def ideal(N, p):
    return 6.0 * (p ** (1.0 / 3.0) - 1.0) / p * N ** (2.0 / 3.0)
loga = sum(math.log(smean / ideal(N, p)) for N, p, _, smean, _ in rows) / len(rows)
a = math.exp(loga)
print('\n### Communication volume of the partition (scripts/partition_study.py)\n')
print('Shared nodes per rank on n^3 hex8 cubes, METIS k-way (bin/dynx-part), against the model')
print('mean = a 6 (NP^(1/3) - 1)/NP N^(2/3) (NP near-cubes cut by planes; a = %.3f fitted for' % a)
print('the jagged cuts). The exchange sends 3 doubles per shared node and neighbour per cycle.\n')
print('| elements N | NP | shared mean | model | error | shared max | max/mean | balance |')
print('|---|---|---|---|---|---|---|---|')
worst = 0.0
ratios = []
for N, p, smax, smean, bal in rows:
    mod = a * ideal(N, p)
    err = (smean - mod) / mod
    worst = max(worst, abs(err))
    ratios.append(smax / smean)
    print('| %d | %d | %.0f | %.0f | %+.1f %% | %d | %.2f | %.4f |' % (N, p, smean, mod, 100 * err,
                                                                      smax, smax / smean, bal))
print('\nLargest model error %.1f %% (mean); max/mean %.2f-%.2f. Extrapolation to NP = 256 (on '
      'paper): ' % (100 * worst, min(ratios), max(ratios))
      + '; '.join('N = %g: %.0f shared nodes per rank on average (%.0f elements per rank), about '
                  '%.1f kB per rank and cycle for the plain exchange (24 B per shared node)'
                  % (N, a * ideal(N, 256), N / 256, a * ideal(N, 256) * 24 / 1000)
                  for N in (1e5, 1e6)) + '. The fixed-order exchange sends one 24-byte value per '
      'element contribution instead of one per node: 3.8 contributions per shared node on the '
      '1e5 box at NP = 2 (mpi_shared_bench), so about 4x those volumes.')
