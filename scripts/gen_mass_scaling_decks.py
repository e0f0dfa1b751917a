#!/usr/bin/python3
"""Decks of the mass-scaling regression cases (tests/regression/mass_scaling_*): a free
steel bar (mm, ms, kg, GPa) of 1 x 1 cross-section, ten hexahedra along x, the sixth of
them short (0.25 long, the others 1), pulled or pushed at x = 0 by a constant nodal force.
Run from the top directory: python3 scripts/gen_mass_scaling_decks.py"""
import os

XS = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 5.25, 6.25, 7.25, 8.25, 9.25]


def deck(title, dt2ms, ms1st=0, endtim=0.003, endmas=0.0, force=-0.025, lctm=0,
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
            '*SET_NODE_LIST', '        10', '         1         2         3         4',
            '*LOAD_NODE_SET', '$#    nsid       dof      lcid        sf',
            '        10         1         1%10.4g' % force,
            '*DEFINE_CURVE', '         1', '                 0.0                 1.0',
            '                 1.0                 1.0']
    out.append('*NODE')
    n = 0
    for x in XS:
        for (y, z) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]:
            n += 1
            out.append('%8d%16.8f%16.8f%16.8f' % (n, x, y, z))
    out.append('*ELEMENT_SOLID')
    for e in range(len(XS) - 1):
        a = 4*e
        out.append('%8d%8d' % (e + 1, 1))
        out.append(''.join('%8d' % k for k in [a + 1, a + 2, a + 3, a + 4,
                                               a + 5, a + 6, a + 7, a + 8]))
    out.append(extra.rstrip('\n')) if extra else None
    out.append('*END')
    return '\n'.join(o for o in out if o is not None) + '\n'


CASES = {
    'mass_scaling_neg': deck('mass scaling DT2MS = -1e-4: the short element lifted to 1e-4',
                             -1.0e-4),
    'mass_scaling_pos': deck('mass scaling DT2MS = +1.1e-4: every element set to 1.1e-4',
                             1.1e-4, force=0.025),
    'mass_scaling_ms1st': deck('mass scaling DT2MS = -1e-4, MS1ST = 1, pushed', -1.0e-4,
                               ms1st=1, force=0.025),
    'mass_scaling_endmas': deck('mass scaling DT2MS = -1e-4 with ENDMAS = 13.5 %', -1.0e-4,
                                endmas=13.5),
    'mass_scaling_restart': deck('mass scaling DT2MS = -1e-4, pushed: restart', -1.0e-4,
                                 force=0.025, endtim=0.006, d3dump=20),
    'mass_scaling_bad_lctm': deck('mass scaling with an undefined LCTM curve', -1.0e-4,
                                  lctm=7),
}

if __name__ == '__main__':
    for name, text in CASES.items():
        d = os.path.join('tests', 'regression', name)
        os.makedirs(d, exist_ok=True)
        with open(os.path.join(d, 'deck.k'), 'w') as f:
            f.write(text)
        print(d)
