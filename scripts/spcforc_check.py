#!/usr/bin/python3
"""Checks of dynx's spcforc file (*DATABASE_SPCFORC, issue 16).

    python3 scripts/spcforc_check.py OUTDIR --bar E A L NODE TSTART TOL

--bar: a bar fixed at x = 0 and pulled at x = L (scripts/gen_spcforc_deck.py): at every
output time t >= TSTART the x force resultant of the SPC reactions equals -E A u/L (u: the
x displacement of NODE at that time, from nodout) within TOL relative to E A u/L, the y and
z resultants are below 1e-9 of it, and each line's resultant is the sum of its node lines
(to the 10 printed digits).
The file is parsed by its labels ('output at time =', 'node=', 'local x,y,z forces =',
'force resultants =').
"""
import sys

from ascii_out import read_columns, unknown_option


def read_spcforc(path):
    recs, t = [], None
    for line in open(path):
        s = line.strip()
        if s.startswith('output at time ='):
            t = float(s.split('=')[1])
            recs.append({'t': t, 'nodes': {}, 'res': None})
        elif s.startswith('node='):
            w = s.replace('=', ' = ').split()
            nid = int(w[2])
            i = w.index('forces')
            recs[-1]['nodes'][nid] = [float(x) for x in w[i + 2:i + 5]]
        elif s.startswith('force resultants ='):
            w = s.split('=')[1].split()
            recs[-1]['res'] = [float(x) for x in w[:3]]
    return recs


def main():
    a = sys.argv[1:]
    out = a.pop(0)
    recs = read_spcforc(out + '/spcforc')
    ok = bool(recs)
    print('spcforc: %d times, %d constrained nodes' % (len(recs), len(recs[0]['nodes'])))
    while a:
        opt = a.pop(0)
        if opt == '--bar':
            e, area, length = float(a.pop(0)), float(a.pop(0)), float(a.pop(0))
            node, t0, tol = int(a.pop(0)), float(a.pop(0)), float(a.pop(0))
            nod = read_columns(out + '/nodout', node)
            worst, worst_yz, worst_sum, n = 0.0, 0.0, 0.0, 0
            for r in recs:
                s = [sum(f[c] for f in r['nodes'].values()) for c in range(3)]
                scale = max(abs(x) for x in r['res']) or 1.0
                worst_sum = max(worst_sum, max(abs(s[c] - r['res'][c]) for c in range(3))/scale)
                if r['t'] < t0 or r['t'] not in nod:
                    continue
                f = e*area*nod[r['t']]['x_disp']/length
                worst = max(worst, abs(r['res'][0] + f)/abs(f))
                worst_yz = max(worst_yz, max(abs(r['res'][1]), abs(r['res'][2]))/abs(f))
                n += 1
            good = n > 0 and worst <= tol and worst_yz <= 1e-9 and worst_sum <= 1e-9
            ok &= good
            print('reaction x vs -E A u/L at %d times t >= %g: largest relative difference '
                  '%.3e (tolerance %g); y, z resultants %.3e of it; node sum vs resultant '
                  '%.3e: %s' % (n, t0, worst, tol, worst_yz, worst_sum,
                                'ok' if good else 'FAIL'))
        else:
            unknown_option(opt)
    sys.exit(0 if ok else 1)


if __name__ == '__main__':
    main()
