#!/usr/bin/python3
"""Shell test decks (mm, ms, kg, GPa): a flat rectangular plate of Belytschko-Lin-Tsay
shells, nx by ny elements, length L along x, width B along y, thickness T.

  gen_shell_deck.py cantilever NX NY [OUT]   clamped at x = 0 (all six DOF), initial
      transverse velocity in the shape of the first cantilever mode (Euler-Bernoulli,
      PR = 0 so that beam and plate theory agree), tip nodes in nodout
  gen_shell_deck.py patch [OUT]              membrane patch test: 5 irregular quadrilaterals
      and 2 triangles, boundary nodes driven with the velocity of a uniform strain rate
  gen_shell_deck.py rotation [OUT]           a free plate spinning as a rigid body about an
      in-plane axis (initial velocity omega x r): no strain, internal energy 0
"""
import math
import sys

E, RHO = 210.0, 7.85e-6


def head(title, tend, dplot, dhist, hist_nodes, pr=0.0, extra=''):
    s = ['*KEYWORD', '*TITLE', title,
         '*CONTROL_TERMINATION', f'{tend:10.4f}',
         '*CONTROL_TIMESTEP', '$   DTINIT    TSSFAC', '       0.0    0.9000',
         '*DATABASE_GLSTAT', f'{dhist:10.6f}',
         '*DATABASE_NODOUT', f'{dhist:10.6f}',
         '*DATABASE_BINARY_D3PLOT', f'{dplot:10.6f}',
         '*DATABASE_HISTORY_NODE', ''.join(f'{n:10d}' for n in hist_nodes),
         '*PART', 'plate', '         1         1         1',
         '*SECTION_SHELL',
         '$    SECID    ELFORM      SHRF       NIP',
         '         1         2  0.833333         3',
         '$       T1',
         '       1.0',
         '*MAT_ELASTIC', '$      MID        RO         E        PR',
         f'         1{RHO:10.3e}{E:10.1f}{pr:10.3f}']
    if extra:
        s.append(extra)
    return s


def grid(nx, ny, lx, ly):
    nodes, elems = [], []
    for j in range(ny + 1):
        for i in range(nx + 1):
            nodes.append((j*(nx + 1) + i + 1, lx*i/nx, ly*j/ny, 0.0))
    for j in range(ny):
        for i in range(nx):
            n1 = j*(nx + 1) + i + 1
            elems.append((j*nx + i + 1, n1, n1 + 1, n1 + nx + 2, n1 + nx + 1))
    return nodes, elems


def node_cards(nodes):
    out = ['*NODE']
    for n, x, y, z in nodes:
        out.append(f'{n:8d}{x:16.8f}{y:16.8f}{z:16.8f}')
    return out


def elem_cards(elems):
    out = ['*ELEMENT_SHELL']
    for e in elems:
        out.append(''.join(f'{k:8d}' for k in (e[0], 1) + tuple(e[1:])))
    return out


def cantilever(nx, ny):
    L, B = 100.0, 10.0
    nodes, elems = grid(nx, ny, L, B)
    bl = 1.8751040687
    sig = (math.cosh(bl) + math.cos(bl))/(math.sinh(bl) + math.sin(bl))

    def phi(x):
        a = bl*x/L
        return 0.5*(math.cosh(a) - math.cos(a) - sig*(math.sinh(a) - math.sin(a)))

    tip = [j*(nx + 1) + nx + 1 for j in range(ny + 1)]
    s = head(f'Cantilever plate {nx}x{ny} BT shells, first mode', 15.0, 1.0, 0.01, tip[:1])
    s += node_cards(nodes) + elem_cards(elems)
    s += ['*INITIAL_VELOCITY_NODE']
    v0 = 1.0e-3        # mm/ms: tip velocity 1e-3 (small rotations)
    for n, x, y, z in nodes:
        if x > 0.0:
            s.append(f'{n:10d}{0.0:10.4g}{0.0:10.4g}{v0*phi(x):10.3e}')
    s += ['*SET_NODE_LIST', '         1']
    clamp = [j*(nx + 1) + 1 for j in range(ny + 1)]
    for k in range(0, len(clamp), 8):
        s.append(''.join(f'{n:10d}' for n in clamp[k:k + 8]))
    s += ['*BOUNDARY_SPC_SET', '         1         0         1         1         1'
          '         1         1         1', '*END']
    return s


def main():
    kind = sys.argv[1]
    if kind == 'cantilever':
        lines = cantilever(int(sys.argv[2]), int(sys.argv[3]))
        out = sys.argv[4] if len(sys.argv) > 4 else None
    else:
        raise SystemExit('unknown kind ' + kind)
    text = '\n'.join(lines) + '\n'
    if out:
        with open(out, 'w') as f:
            f.write(text)
    else:
        sys.stdout.write(text)


if __name__ == '__main__':
    main()
