#!/usr/bin/env python3
"""Large-input decks for the set-up cost checks of issue 15 (docs/errors.md, "Large inputs"):
  history.k  a box of 60 x 60 x 55 hex8 (208 376 nodes) with every node in
             *DATABASE_HISTORY_NODE (8 ids per card) and *DATABASE_NODOUT
  parts.k    20 000 hex8 in a row, each its own *PART (one section and material)
  longline.k the Taylor bar with a 2 MB comment line and a node card with 2 MB of blanks
Usage: gen_large_input_decks.py OUTDIR [scale]   (scale < 1 shrinks the first two, e.g. 0.1)
Time the read and set-up with: bin/dynx -i OUTDIR/X.k --check"""
import os
import sys
from dxmesh import box_cards

out = sys.argv[1]
scale = float(sys.argv[2]) if len(sys.argv) > 2 else 1.0
os.makedirs(out, exist_ok=True)
HEAD = ('*KEYWORD\n*CONTROL_TERMINATION\n       1.0        10\n'
        '*SECTION_SOLID\n         1         1\n'
        '*MAT_ELASTIC\n         1    7.8E-6     210.0       0.3\n')


def box(f, nx, ny, nz, part_of):
    for line in box_cards(nx, ny, nz, 1, 1, 1, part_of):
        f.write(line)
    return (nx + 1) * (ny + 1) * (nz + 1)


n = max(2, round(60 * scale ** (1 / 3)))
with open(os.path.join(out, 'history.k'), 'w') as f:
    f.write(HEAD + '*PART\nbox\n         1         1         1\n')
    nn = box(f, n, n, n - 5 if n > 10 else n, lambda e: 1)
    f.write('*DATABASE_NODOUT\n     1.0\n*DATABASE_HISTORY_NODE\n')
    for a in range(1, nn + 1, 8):
        f.write(''.join('%10d' % i for i in range(a, min(a + 8, nn + 1))) + '\n')
npart = max(10, round(20000 * scale))
with open(os.path.join(out, 'parts.k'), 'w') as f:
    f.write(HEAD)
    for p in range(1, npart + 1):
        f.write('*PART\npart %d\n%10d         1         1\n' % (p, p))
    box(f, npart, 1, 1, lambda e: e)
src = open(os.path.join(os.path.dirname(__file__), '..', 'decks', 'taylor_bar', 'deck.k')).read()
lines = src.split('\n')
i = next(k for k, l in enumerate(lines) if l.startswith('*NODE'))
j = i + 1
while lines[j].startswith('$'):
    j += 1
lines[j] += ' ' * 2_000_000
lines.insert(i, '$' + 'x' * 2_000_000)
with open(os.path.join(out, 'longline.k'), 'w') as f:
    f.write('\n'.join(lines))
