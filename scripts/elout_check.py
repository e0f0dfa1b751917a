#!/usr/bin/python3
"""Checks of dynx's elout file (*DATABASE_ELOUT with *DATABASE_HISTORY_SOLID, issue 16).

    python3 scripts/elout_check.py OUTDIR --bar E A L NODE TSTART TOL [--reaction EID]

The file is parsed as LS-DYNA's elout readers do: a record starts at 'e l e m e n t   s t r e s s
c a l c u l a t i o n s   f o r   t i m e  s t e p N ( at time t )', then per element a line
'id- part' and a line '1- elastic|plastic' with sig-xx sig-yy sig-zz sig-xy sig-yz sig-zx and
the effective plastic strain.
--bar E A L NODE TSTART TOL   a bar of cross-section A (nu = 0) fixed at x = 0 and pulled at
        x = L (scripts/gen_spcforc_deck.py): at every output time t >= TSTART every history
        element's sig-xx is the bar's stress E u/L (u: the x displacement of NODE, nodout)
        within TOL relative (the quasi-static error of the pull, as spcforc_bar's); its other
        five stress components stay below 1e-12 of sig-xx (nu = 0: they vanish but for
        round-off, a few ulps times some thousand operations) and its plastic strain is 0
        ('elastic').
--reaction EID   element EID (the one at the fixed end) carries the spcforc reaction: at
        every time sig-xx A equals -(the x force resultant) within 1e-9 relative (the
        element's nodal forces are the reaction; both printed to 10 digits).
"""
import re
import sys

from ascii_out import read_columns, unknown_option

HEAD = re.compile(r'e l e m e n t   s t r e s s   c a l c u l a t i o n s   f o r   '
                  r't i m e  s t e p\s+(\d+) \( at time\s+(\S+) \)')


def read_elout(path):
    recs, eid = [], None
    for line in open(path):
        m = HEAD.search(line)
        if m:
            recs.append({'t': float(m.group(2)), 'e': {}})
            continue
        w = line.split()
        if recs and len(w) == 2 and w[0].endswith('-') and w[0][:-1].isdigit():
            eid = int(w[0][:-1])
        elif recs and len(w) == 9 and w[0] == '1-' and w[1] in ('elastic', 'plastic'):
            recs[-1]['e'][eid] = (w[1], [float(x) for x in w[2:]])
    return recs


def main():
    a = sys.argv[1:]
    out = a.pop(0)
    recs = read_elout(out + '/elout')
    ok = bool(recs) and bool(recs[-1]['e'])
    print('elout: %d times, elements %s' % (len(recs), sorted(recs[-1]['e']) if recs else []))
    area = None
    while a:
        opt = a.pop(0)
        if opt == '--bar':
            e, area, length = float(a.pop(0)), float(a.pop(0)), float(a.pop(0))
            node, t0, tol = int(a.pop(0)), float(a.pop(0)), float(a.pop(0))
            nod = read_columns(out + '/nodout', node)
            worst, worst_o, n, plastic = 0.0, 0.0, 0, False
            for r in recs:
                if r['t'] < t0 or r['t'] not in nod:
                    continue
                s = e*nod[r['t']]['x_disp']/length
                for state, v in r['e'].values():
                    worst = max(worst, abs(v[0] - s)/abs(s))
                    worst_o = max(worst_o, max(abs(x) for x in v[1:6])/abs(v[0]))
                    plastic |= state != 'elastic' or v[6] != 0.0
                n += 1
            good = n > 0 and worst <= tol and worst_o <= 1e-12 and not plastic
            ok &= good
            print('sig-xx vs E u/L at %d times t >= %g: largest relative difference %.3e '
                  '(tolerance %g); other components %.3e of sig-xx; plastic: %s: %s'
                  % (n, t0, worst, tol, worst_o, plastic, 'ok' if good else 'FAIL'))
        elif opt == '--reaction':
            eid = int(a.pop(0))
            res = {}
            t = None
            for line in open(out + '/spcforc'):
                s = line.strip()
                if s.startswith('output at time ='):
                    t = float(s.split('=')[1])
                elif s.startswith('force resultants ='):
                    res[t] = float(s.split('=')[1].split()[0])
            worst, n = 0.0, 0
            for r in recs:
                if r['t'] in res and res[r['t']] != 0.0:
                    worst = max(worst, abs(r['e'][eid][1][0]*area + res[r['t']])/abs(res[r['t']]))
                    n += 1
            good = n > 1 and worst <= 1e-9
            ok &= good
            print('element %d: sig-xx A vs -(spcforc x resultant) at %d times: largest relative '
                  'difference %.3e (bound 1e-9): %s' % (eid, n, worst, 'ok' if good else 'FAIL'))
        else:
            unknown_option(opt)
    sys.exit(0 if ok else 1)


if __name__ == '__main__':
    main()
