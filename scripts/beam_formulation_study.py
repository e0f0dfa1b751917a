#!/usr/bin/python3
"""Why dynx's beam is the resultant beam (ELFORM 2) and not Hughes-Liu (ELFORM 1) first:
the first bending frequency of the cantilever of tests/regression/beam_cantilever (L = 100,
section 2 x 1, bending about s: I/A = 1/12, E = 210, PR = 0, rho = 7.85e-6) on N elements,
small-deformation element matrices with the explicit codes' lumped (diagonal) mass:
  - resultant beam: the cubic Hermite (Euler-Bernoulli) bending stiffness of dx_beam_bs;
  - Hughes-Liu: for an elastic material and small deformation its bending is a 2-node
    Timoshenko element with linear w and theta and one integration point along the axis
    (Hughes & Liu 1981, CMAME 26:331-362: the degenerated-continuum beam, reduced
    integration against shear locking), shear factor 5/6.
Both with the nodal mass rho A h/2 and dx_beam_bs's rotary inertia m max((ISS+ITT)/A, h**2/12).
Prints the relative error of the first frequency against Euler-Bernoulli for N = 4 .. 64
(plain python3: inverse iteration with a dense solve; docs/design.md "Beams").
"""
import math

L, E, NU, RHO = 100.0, 210.0, 0.0, 7.85e-6
B, H = 2.0, 1.0
A, I_S, I_T = B*H, B*H**3/12.0, H*B**3/12.0
G = E/(2.0*(1.0 + NU))
KAPPA = 5.0/6.0


def solve(a, b):
    """x = a^-1 b (Gaussian elimination with partial pivoting; a is copied)"""
    n = len(b)
    a = [row[:] + [b[i]] for i, row in enumerate(a)]
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(a[r][c]))
        a[c], a[p] = a[p], a[c]
        for r in range(c + 1, n):
            f = a[r][c]/a[c][c]
            if f != 0.0:
                for j in range(c, n + 1):
                    a[r][j] -= f*a[c][j]
    x = [0.0]*n
    for r in range(n - 1, -1, -1):
        x[r] = (a[r][n] - sum(a[r][j]*x[j] for j in range(r + 1, n)))/a[r][r]
    return x


def first_freq(n, kind):
    h = L/n
    nd = 2*(n + 1)
    k = [[0.0]*nd for _ in range(nd)]
    m = [0.0]*nd
    for e in range(n):
        d = [2*e, 2*e + 1, 2*e + 2, 2*e + 3]   # w1 th1 w2 th2
        if kind == 'resultant':
            c = E*I_S/h**3
            ke = [[12*c, 6*h*c, -12*c, 6*h*c], [6*h*c, 4*h*h*c, -6*h*c, 2*h*h*c],
                  [-12*c, -6*h*c, 12*c, -6*h*c], [6*h*c, 2*h*h*c, -6*h*c, 4*h*h*c]]
        else:
            cb = E*I_S/h
            bs = [-1.0/h, -0.5, 1.0/h, -0.5]
            ke = [[KAPPA*G*A*h*bs[i]*bs[j] for j in range(4)] for i in range(4)]
            for i, j, v in ((1, 1, cb), (3, 3, cb), (1, 3, -cb), (3, 1, -cb)):
                ke[i][j] += v
        for i in range(4):
            for j in range(4):
                k[d[i]][d[j]] += ke[i][j]
        mn = 0.5*RHO*A*h
        jn = mn*max((I_S + I_T)/A, h*h/12.0)
        for i, v in zip(d, (mn, jn, mn, jn)):
            m[i] += v
    kf = [row[2:] for row in k[2:]]             # node 1 clamped
    mf = m[2:]
    y = [1.0]*len(mf)
    lam = 0.0
    for _ in range(200):                        # inverse iteration: K x = M y
        x = solve(kf, [mi*yi for mi, yi in zip(mf, y)])
        num = sum(xi*mi*yi for xi, mi, yi in zip(x, mf, y))
        den = sum(xi*mi*xi for xi, mi in zip(x, mf))
        nx = math.sqrt(den)
        y = [xi/nx for xi in x]
        if abs(num/den - lam) <= 1e-14*abs(num/den):
            break
        lam = num/den
    return math.sqrt(rayleigh(kf, mf, y))


def rayleigh(kf, mf, y):
    """y.K y / y.M y"""
    ky = [sum(r[j]*y[j] for j in range(len(y))) for r in kf]
    return sum(a*b for a, b in zip(y, ky))/sum(mi*yi*yi for mi, yi in zip(mf, y))


def main():
    w_eb = 1.8751040687**2*math.sqrt(E*I_S/(RHO*A*L**4))
    print('N   resultant (cubic)   Hughes-Liu (linear, 1 point)')
    for n in (4, 8, 16, 32, 64):
        er = abs(first_freq(n, 'resultant') - w_eb)/w_eb
        eh = abs(first_freq(n, 'hl') - w_eb)/w_eb
        print(f'{n:<4d}{er:12.3e}{eh:22.3e}')


if __name__ == '__main__':
    main()
