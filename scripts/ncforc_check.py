#!/usr/bin/python3
"""Checks of dynx's ncforc file (*DATABASE_NCFORC, issue 16) against rcforc and mechanics.

    python3 scripts/ncforc_check.py OUTDIR [--min-force F]

The file is parsed as LS-DYNA's ncforc readers do: a block starts at a line holding 'forces'
and '(t= t)' whose fifth word is the interface id and sixth its side (slave or master); four
lines later come pairs of lines 'node fx fy fz pressure' / 'x y z', up to a blank line.
At every time that rcforc also has (*DATABASE_RCFORC, the same DT): each side's nodal forces
add up to rcforc's resultant of that side (per interface), and the two sides to zero
(Newton's third law: a slave node's force goes to its master segment's nodes times shape
functions that sum to 1). Tolerance: every number is printed to 10 significant digits
(relative rounding 5e-11), so a sum of n terms is off by at most 5e-11 times the sum of
their magnitudes, plus the resultant's own rounding: the bound is 1e-10 x (sum |f_i| +
|resultant|). --min-force F: some side resultant exceeds F at some time (not vacuous).
"""
import sys

from ascii_out import unknown_option


def read_ncforc(path):
    blocks = {}          # (t, interface, side) -> list of (node, f)
    cur = None
    lines = open(path).read().split('\n')
    i = 0
    while i < len(lines):
        s = lines[i]
        if 'forces' in s and '(t=' in s:
            w = s.split()
            t = float(s.split('t=')[1].split(')')[0])
            cur = blocks.setdefault((t, int(w[4]), w[5]), [])
            i += 4
            while i + 1 < len(lines) and lines[i].strip():
                v = lines[i].split()
                cur.append((int(v[0]), [float(x) for x in v[1:4]]))
                i += 2
            continue
        i += 1
    return blocks


def main():
    a = sys.argv[1:]
    out = a.pop(0)
    blocks = read_ncforc(out + '/ncforc')
    rc = {}
    for line in open(out + '/rcforc'):
        if line.lstrip()[:1] not in tuple('+-.0123456789'):
            continue
        v = line.split()
        rc[(float(v[0]), int(v[1]))] = ([float(x) for x in v[2:5]], [float(x) for x in v[5:8]])
    ok = bool(blocks)
    times = sorted({k[0] for k in blocks})
    print('ncforc: %d times, %d blocks' % (len(times), len(blocks)))
    worst, worst3, n, fmax = 0.0, 0.0, 0, 0.0
    for (t, iface), (fs, fm) in rc.items():
        if (t, iface, 'slave') not in blocks:
            continue
        sides = []
        for side, ref in (('slave', fs), ('master', fm)):
            nodes = blocks[(t, iface, side)]
            tot = [sum(f[c] for _, f in nodes) for c in range(3)]
            mag = sum(abs(f[c]) for _, f in nodes for c in range(3))
            for c in range(3):
                bound = 1e-10*(mag + abs(ref[c])) + 1e-300
                worst = max(worst, abs(tot[c] - ref[c])/bound)
            fmax = max(fmax, max(abs(x) for x in ref))
            sides.append((tot, mag))
        for c in range(3):
            bound = 1e-10*(sides[0][1] + sides[1][1]) + 1e-300
            worst3 = max(worst3, abs(sides[0][0][c] + sides[1][0][c])/bound)
        n += 1
    good = n > 0 and worst <= 1.0 and worst3 <= 1.0
    ok &= good
    print('side sums vs rcforc resultants at %d (time, interface) pairs: largest difference '
          '%.3f of the bound; slave + master: %.3f of the bound: %s'
          % (n, worst, worst3, 'ok' if good else 'FAIL'))
    while a:
        opt = a.pop(0)
        if opt == '--min-force':
            f = float(a.pop(0))
            good = fmax > f
            ok &= good
            print('largest side resultant %.6e > %g: %s' % (fmax, f, 'ok' if good else 'FAIL'))
        else:
            unknown_option(opt)
    sys.exit(0 if ok else 1)


if __name__ == '__main__':
    main()
