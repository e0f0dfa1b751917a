#!/usr/bin/python3
"""Checks of dynx's sleout file (*DATABASE_SLEOUT, issue 16) against glstat.

    python3 scripts/sleout_check.py OUTDIR [--min-total E]

At every sleout time that glstat also has: the summary's total energy equals glstat's
sliding_interface energy, and the summary's slave and master energies are the sums of the
interface lines. Tolerance: both files print 10 significant digits (relative rounding 5e-11)
and the sums differ only in grouping (per interface and side, against per node: a few ulps
of the largest side's work per cycle, below 1e-13 of it over 1000 cycles), so 2e-10 times
the largest magnitude of a side's energy (slave or master) over the run. The slave and master
energies can be much larger than their sum (the work on two moving bodies nearly cancels),
which is why they set the scale.
--min-total E: the largest total energy over the run is at least E (the check is not vacuous).
--order I J DT: interface J's energy stays exactly 0 until at least DT after interface I's
             first becomes nonzero (J closes later), and both become nonzero.
The file is parsed by its labels ('time =', 'interface=', 'slave=', 'master=', 'total=',
'summary', 'total energy=').
"""
import re
import sys

from ascii_out import read_columns, unknown_option

PAIR = re.compile(r'([a-z]+(?: energy)?)=\s*([-+0-9.Ee]+)')


def read_sleout(path):
    recs = []
    for line in open(path):
        s = line.strip()
        if s.startswith('time ='):
            recs.append({'t': float(s.split('=')[1]), 'if': {}, 'sum': None})
        elif s.startswith('interface='):
            d = {k.strip(): float(v) for k, v in PAIR.findall(s)}
            recs[-1]['if'][int(d['interface'])] = d
        elif s.startswith('summary'):
            recs[-1]['sum'] = {k.strip(): float(v) for k, v in PAIR.findall(s)}
    return recs


def main():
    a = sys.argv[1:]
    out = a.pop(0)
    recs = read_sleout(out + '/sleout')
    g = read_columns(out + '/glstat')
    ok = bool(recs)
    scale = max([abs(r['sum'][k]) for r in recs for k in ('slave', 'master', 'total energy')]
                + [abs(d[k]) for r in recs for d in r['if'].values() for k in ('slave', 'master')])
    bound = 2e-10*scale
    worst_g, worst_s, n = 0.0, 0.0, 0
    for r in recs:
        for k in ('slave', 'master'):
            worst_s = max(worst_s, abs(sum(d[k] for d in r['if'].values()) - r['sum'][k]))
        if r['t'] in g:
            worst_g = max(worst_g, abs(r['sum']['total energy'] - g[r['t']]['sliding_interface']))
            n += 1
    good = n > 0 and worst_g <= bound and worst_s <= bound
    ok &= good
    print('sleout: %d times, %d interface(s); total vs glstat sliding_interface at %d times: '
          'largest difference %.3e; summary vs interface lines %.3e (bound 2e-10 x %.6e = '
          '%.3e): %s' % (len(recs), len(recs[0]['if']), n, worst_g, worst_s, scale, bound,
                         'ok' if good else 'FAIL'))
    while a:
        opt = a.pop(0)
        if opt == '--min-total':
            e = float(a.pop(0))
            top = max(r['sum']['total energy'] for r in recs)
            good = top >= e
            ok &= good
            print('largest total energy %.6e (at least %g): %s' % (top, e, 'ok' if good else 'FAIL'))
        elif opt == '--order':
            i, j, dt = int(a.pop(0)), int(a.pop(0)), float(a.pop(0))

            def first(k):
                ts = [r['t'] for r in recs if r['if'][k]['total'] != 0.0]
                return ts[0] if ts else None
            ti, tj = first(i), first(j)
            good = ti is not None and tj is not None and tj - ti >= dt
            ok &= good
            print('interface %d first nonzero at %s, interface %d at %s (at least %g later): %s'
                  % (i, ti, j, tj, dt, 'ok' if good else 'FAIL'))
        else:
            unknown_option(opt)
    sys.exit(0 if ok else 1)


if __name__ == '__main__':
    main()
