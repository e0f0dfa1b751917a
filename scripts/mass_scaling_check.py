#!/usr/bin/python3
"""Checks of the mass-scaling regression cases (tests/regression/mass_scaling_*, decks from
scripts/gen_mass_scaling_decks.py; the derivation: tests/regression/mass_scaling_neg/
README.md). Usage: mass_scaling_check.py MODE OUTDIR, MODE one of neg, pos, ms1st, endmas.

The bar: 1 x 1 cross-section meshed 2 x 2, ten elements along x of lengths LEN, steel
rho = 7.85e-6, E = 210, nu = 0.3 (mm, ms, kg, GPa), TSSFAC 0.9, a constant force F = 9 x 0.01 at
x = 0. An element's step at cycle 0 (at rest: no bulk viscosity) is L/c,
c = sqrt((K + 4G/3)/rho), L = V/A_max: 0.25/0.5 = 0.5 for a long element (0.5 x 0.5 x 1),
0.0625/0.25 = 0.25 for a short one (0.5 x 0.5 x 0.25). No element carries half of its nodes'
mass (phim <= 0.42), so dx_hex8's element bound does not apply. The mass that lifts a step
dt_e to a target d: dm = rho V ((d/dt_e)**2 - 1) (the step goes as sqrt(mass))."""
import math
import sys

RHO, E, NU, TSSFAC = 7.85e-6, 210.0, 0.3, 0.9
LEN = [1.0, 1.0, 1.0, 1.0, 1.0, 0.25, 1.0, 1.0, 1.0, 1.0]
F = 0.09
MODEL_MASS = RHO*sum(LEN)
ENDMAS = 3.3
# glstat prints 11 significant digits: a value read back is within 5e-11 relative
PRINT = 1.0e-10


def glstat(outdir):
    cols, rows = None, []
    with open(outdir + '/glstat') as f:
        for line in f:
            if line.lstrip()[:1] not in tuple('+-.0123456789'):
                cols = line.lstrip('#').split()   # '# time ...' or 'time ...' (columnhead form)
            else:
                rows.append(dict(zip(cols, [float(x) for x in line.split()])))
    return rows


def element_steps():
    """(volume, step) of each element at cycle 0 (at rest), 4 per length."""
    k = E/(3.0*(1.0 - 2.0*NU))
    g = E/(2.0*(1.0 + NU))
    c = math.sqrt((k + 4.0*g/3.0)/RHO)
    out = []
    for le in LEN:
        vol = 0.25*le
        out += [(vol, vol/max(0.25, 0.5*le)/c)]*4
    return out


def close(a, b, rel):
    return abs(a - b) <= rel*max(abs(a), abs(b))


def main():
    mode, out = sys.argv[1], sys.argv[2]
    rows = glstat(out)
    fail = []
    dts = element_steps()
    if mode in ('neg', 'ms1st', 'endmas'):
        d = 6.0e-5
        dm0 = sum(RHO*v*((d/dt)**2 - 1.0) for v, dt in dts if dt < d)
        nscaled = sum(1 for v, dt in dts if dt < d)
    else:
        d = 7.0e-5
        dm0 = sum(RHO*v*((d/dt)**2 - 1.0) for v, dt in dts)
        nscaled = len(dts)
    r0 = rows[0]
    if not close(r0['added_mass'], dm0, PRINT):
        fail.append('added mass at cycle 0 %.12e, analytic %.12e' % (r0['added_mass'], dm0))
    if not close(r0['percent_increase'], 100.0*dm0/MODEL_MASS, PRINT):
        fail.append('percentage %.12e, analytic %.12e' % (r0['percent_increase'],
                                                          100.0*dm0/MODEL_MASS))
    if not close(r0['dt'], TSSFAC*d, PRINT):
        fail.append('first step %.12e, TSSFAC*|DT2MS| = %.12e' % (r0['dt'], TSSFAC*d))
    added = [r['added_mass'] for r in rows]
    if mode != 'ms1st':
        # every cycle: the step never below TSSFAC*|DT2MS|, the added mass never decreases
        low = [r for r in rows if r['dt'] < TSSFAC*d*(1.0 - PRINT)]
        if low:
            fail.append('%d glstat steps below TSSFAC*|DT2MS| (first %.12e at t %.6e)'
                        % (len(low), low[0]['dt'], low[0]['time']))
        if any(b < a for a, b in zip(added, added[1:])):
            fail.append('added mass decreases')
    if mode == 'ms1st':
        # scaling at cycle 0 only: the added mass stays, and with it the momentum is exactly
        # the impulse of the load, F (t + dt/2) (v at n+1/2), to round-off
        if any(a != added[0] for a in added):
            fail.append('MS1ST = 1: the added mass changed after cycle 0')
        for r in rows:
            p = F*(r['time'] + 0.5*r['dt'])
            if abs(r['xmom'] - p) > PRINT*p:
                fail.append('x momentum %.12e at t %.6e, impulse %.12e' % (r['xmom'],
                                                                            r['time'], p))
                break
    if mode == 'endmas':
        last = rows[-1]
        if not last['percent_increase'] > ENDMAS:
            fail.append('ENDMAS: the last line has %.6e %% <= %g' % (last['percent_increase'], ENDMAS))
        if any(r['percent_increase'] > ENDMAS for r in rows[:-1]):
            fail.append('ENDMAS: the run went on past %g %%' % ENDMAS)
        if not last['time'] < 3.0e-3:
            fail.append('ENDMAS: the run reached the end time')
    for f in fail:
        print('FAIL: ' + f)
    if not fail:
        print('ok: %s: cycle 0 added mass %.10e (%d element(s) scaled, analytic %.10e), '
              '%.6f %%, first step %.6e; %d glstat lines' % (mode, r0['added_mass'], nscaled,
                                                            dm0, r0['percent_increase'],
                                                            r0['dt'], len(rows)))
    return 1 if fail else 0


if __name__ == '__main__':
    sys.exit(main())
