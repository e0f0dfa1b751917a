#!/usr/bin/env python3
"""Observed orders of convergence and Richardson extrapolation for the studies (issue 23).

Standard library only; imported by scripts/studies.py, scripts/studies_order.py and
scripts/studies_emc.py.

- pair_orders(h, e): observed order between successive resolutions, p_i = ln(e_i/e_(i+1)) /
  ln(h_i/h_(i+1)), from errors e against an exact (or reference) answer. None where an error
  is zero or the two have opposite signs (the sequence crosses the reference: no order).
- richardson(h, f): three solutions f1, f2, f3 on h1 > h2 > h3, no reference needed. Observed
  order p, extrapolated value f_ext and the grid convergence index of the finest solution
  (GCI = Fs |f3 - f2| / (r^p - 1), Fs = 1.25 for three meshes), following Roache (1998),
  "Verification and Validation in Computational Science and Engineering", and Celik et al.
  (2008), "Procedure for estimation and reporting of uncertainty due to discretization in CFD
  applications", J. Fluids Eng. 130, 078001, whose fixed-point iteration handles unequal
  refinement ratios r21 = h1/h2, r32 = h2/h3. Oscillatory convergence (the differences change
  sign) gives no order: returned as None with the reason.
"""
import math


def pair_orders(h, e):
    out = []
    for i in range(len(h) - 1):
        a, b = e[i], e[i + 1]
        if a is None or b is None or a == 0 or b == 0 or (a > 0) != (b > 0) or h[i] == h[i + 1]:
            out.append(None)
        else:
            out.append(math.log(abs(a) / abs(b)) / math.log(h[i] / h[i + 1]))
    return out


def richardson(h, f, fs=1.25):
    """h1 > h2 > h3 (coarse to fine), f the three solutions. Returns a dict with p, f_ext,
    gci (absolute), or p None and 'why'."""
    h1, h2, h3 = h
    f1, f2, f3 = f
    r21, r32 = h1 / h2, h2 / h3
    e21, e32 = f2 - f1, f3 - f2
    if e21 == 0 or e32 == 0:
        return {'p': None, 'why': 'two solutions equal'}
    if (e21 > 0) != (e32 > 0):
        return {'p': None, 'why': 'oscillatory (differences %+.3g, %+.3g)' % (e21, e32)}
    # Celik et al. (2008), eq. (3), their index 1 = the finest mesh:
    # p = |ln|eC/eF| + ln((rf^p - s)/(rc^p - s))| / ln rf, fixed-point iteration
    rc, rf = r21, r32
    eC, eF = f1 - f2, f2 - f3
    s = 1.0
    p = abs(math.log(abs(eC / eF))) / math.log(rf)
    for _ in range(500):
        pn = abs(math.log(abs(eC / eF)) + math.log((rf ** p - s) / (rc ** p - s))) / math.log(rf)
        if abs(pn - p) < 1e-13:
            p = pn
            break
        p = pn
    if not math.isfinite(p) or p <= 0:
        return {'p': None, 'why': 'no positive order'}
    f_ext = f3 + e32 / (r32 ** p - 1.0)
    gci = fs * abs(e32) / (r32 ** p - 1.0)
    return {'p': p, 'f_ext': f_ext, 'gci': gci, 'r21': r21, 'r32': r32}


def fmt_order(p):
    return '-' if p is None else '%.2f' % p


def self_test():
    # f = 1 + 0.3 h^2 on unequal ratios: p = 2, f_ext = 1 exactly
    h = (1.0, 0.6, 0.25)
    f = [1.0 + 0.3 * x ** 2 for x in h]
    r = richardson(h, f)
    assert abs(r['p'] - 2.0) < 1e-9 and abs(r['f_ext'] - 1.0) < 1e-12, r
    o = pair_orders([0.4, 0.2, 0.1], [1.6e-2, 4e-3, 1e-3])
    assert all(abs(x - 2.0) < 1e-12 for x in o), o
    assert pair_orders([2.0, 1.0], [1.0, -0.5]) == [None]
    assert richardson((3.0, 2.0, 1.0), (1.0, 2.0, 1.5))['p'] is None
    print('study_order: self test passed')


if __name__ == '__main__':
    self_test()
