#!/usr/bin/python3
"""Decks of the mass-scaling regression cases (tests/regression/mass_scaling_*): a free
steel bar (mm, ms, kg, GPa) of 1 x 1 cross-section meshed 2 x 2, ten elements along x, the
sixth of them short (0.25 long, the others 1), pulled or pushed at x = 0 by a constant force
(0.01 on each of the 9 nodes there). (2 x 2 across: no element carries half of its nodes' mass, so
every step is L/c; in a one-element-wide bar the interior elements sit at phim = 1/2, the
threshold of dx_hex8's element bound, where round-off picks the formula.)
Run from the top directory: python3 scripts/gen_mass_scaling_decks.py"""
import os

ENDMAS_PCT = 3.3
XS = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 5.25, 6.25, 7.25, 8.25, 9.25]


def deck(title, dt2ms, ms1st=0, endtim=0.003, endmas=0.0, force=-0.01, lctm=0,
         extra='', glstat=1.0e-4, d3dump=0):
    out = ['*KEYWORD', '*TITLE', title, '*CONTROL_TERMINATION',
           '$#  endtim    endcyc     dtmin    endeng    endmas',
           '%10.4g%10d%10.1f%10.1f%10.4g' % (endtim, 0, 0.0, 0.0, endmas),
           '*CONTROL_TIMESTEP',
           '$#  dtinit    tssfac      isdo    tslimt     dt2ms      lctm     erode     ms1st',
           '%10.1f%10.2f%10d%10.1f%10.4g%10d%10d%10d' % (0.0, 0.9, 0, 0.0, dt2ms, lctm, 0,
                                                         ms1st),
           '*DATABASE_GLSTAT', '%10.4g' % glstat,
           '*DATABASE_NODOUT', '%10.4g' % glstat,
           '*DATABASE_HISTORY_NODE', '         1        41']
    if d3dump:
        out += ['*DATABASE_BINARY_D3DUMP', '%10d' % d3dump]
    out += ['*PART', 'bar', '         1         1         1',
            '*SECTION_SOLID', '         1         1',
            '*MAT_ELASTIC', '$#     mid        ro         e        pr',
            '         1   7.85E-6     210.0       0.3',
            '*SET_NODE_LIST', '        10', ''.join('%10d' % k for k in range(1, 9)),
            '%10d' % 9,
            '*LOAD_NODE_SET', '$#    nsid       dof      lcid        sf',
            '        10         1         1%10.4g' % force,
            '*DEFINE_CURVE', '         1', '                 0.0                 1.0',
            '                 1.0                 1.0']
    out.append('*NODE')
    for s_, x in enumerate(XS):
        for j in range(3):
            for k in range(3):
                out.append('%8d%16.8f%16.8f%16.8f' % (9*s_ + 3*j + k + 1, x, 0.5*j, 0.5*k))
    out.append('*ELEMENT_SOLID')
    e = 0
    for s_ in range(len(XS) - 1):
        for j in range(2):
            for k in range(2):
                face = [(j, k), (j + 1, k), (j + 1, k + 1), (j, k + 1)]
                a = [9*s_ + 3*jj + kk + 1 for (jj, kk) in face]
                e += 1
                out.append('%8d%8d' % (e, 1))
                out.append(''.join('%8d' % n for n in a + [n + 9 for n in a]))
    out.append(extra.rstrip('\n')) if extra else None
    out.append('*END')
    return '\n'.join(o for o in out if o is not None) + '\n'


CASES = {
    'mass_scaling_neg': deck('mass scaling DT2MS = -6e-5: the short elements lifted to 6e-5',
                             -6.0e-5),
    'mass_scaling_pos': deck('mass scaling DT2MS = +7e-5: every element set to 7e-5',
                             7.0e-5, force=0.01),
    'mass_scaling_ms1st': deck('mass scaling DT2MS = -6e-5, MS1ST = 1, pushed', -6.0e-5,
                               ms1st=1, force=0.01),
    'mass_scaling_endmas': deck('mass scaling DT2MS = -6e-5 with ENDMAS = %g %%' % ENDMAS_PCT,
                                -6.0e-5, endmas=ENDMAS_PCT),
    'mpi_mass_scaling': deck('mass scaling DT2MS = +7e-5, pushed, under MPI', 7.0e-5,
                             force=0.01, endtim=0.004),
    'mass_scaling_bad_lctm': deck('mass scaling with an undefined LCTM curve', -6.0e-5,
                                  lctm=7),
}

if __name__ == '__main__':
    for name, text in CASES.items():
        d = os.path.join('tests', 'regression', name)
        os.makedirs(d, exist_ok=True)
        with open(os.path.join(d, 'deck.k'), 'w') as f:
            f.write(text)
        print(d)
