#!/usr/bin/env python3
"""Rewrite a hexahedral deck (as scripts/gen_wave_deck.py writes it: *ELEMENT_SOLID in the
two-line format, one *SECTION_SOLID) into the element families of dx_element_types:
  tet     every hexahedron split into 6 tetrahedra around its diagonal N1-N7 (Kuhn; conforming
          between translated cells), written in LS-DYNA's tetrahedron format
          N1 N2 N3 N4 N4 N4 N4 N4 under *SECTION_SOLID ELFORM 10
  mixed   the bar cut in four along x: hexahedra (part 1), pentahedra written as degenerate
          hexahedra N1 N2 N3 N3 N5 N6 N7 N7 (part 2, ELFORM 1: they stay hexahedra), ELFORM 10
          tetrahedra (part 3) and degenerate tetrahedra N1 N2 N3 N3 N4 N4 N4 N4 (part 4,
          ELFORM 1), with *CONTROL_SOLID ESORT = 1 so part 4's become ELFORM 10
Optional --nodout DT rewrites the *DATABASE_NODOUT interval.
Usage: gen_solid_variants.py {tet,mixed} in.k out.k [--nodout DT]"""
import argparse

KUHN = [(1, 2, 3, 7), (1, 3, 4, 7), (1, 4, 8, 7), (1, 8, 5, 7), (1, 5, 6, 7), (1, 6, 2, 7)]
WEDGES = [(1, 2, 3, 3, 5, 6, 7, 7), (1, 3, 4, 4, 5, 7, 8, 8)]

ap = argparse.ArgumentParser()
ap.add_argument('kind', choices=['tet', 'mixed'])
ap.add_argument('inp')
ap.add_argument('out')
ap.add_argument('--nodout', type=float)
a = ap.parse_args()
lines = open(a.inp).read().split('\n')
head, elems, tail = [], [], []
i = 0
while not lines[i].startswith('*ELEMENT_SOLID'):
    head.append(lines[i])
    i += 1
i += 1
while not lines[i].startswith('*'):
    eid = int(lines[i].split()[0])
    nodes = [int(t) for t in lines[i + 1].split()]
    elems.append((eid, nodes))
    i += 2
tail = lines[i:]
out = []
k = 0
while k < len(head):
    ln = head[k]
    if ln.startswith('*DATABASE_NODOUT') and a.nodout:
        out += [ln, '%10.6f' % a.nodout]
        k += 2
        continue
    if ln.startswith('*PART') and a.kind == 'mixed':
        out.append('*CONTROL_SOLID\n$    ESORT\n         1')
        for p, (title, form) in enumerate([('hexahedra', 1), ('pentahedra (degenerate hex)', 1),
                                           ('tetrahedra ELFORM 10', 10),
                                           ('degenerate tetrahedra, ESORT', 1)]):
            out += ['*PART', title, '%10d%10d%10d' % (p + 1, p + 1, 1),
                    '*SECTION_SOLID', '%10d%10d' % (p + 1, form)]
        k += 5           # *PART, title, ids, *SECTION_SOLID, secid elform
        continue
    if ln.startswith('*SECTION_SOLID') and a.kind == 'tet':
        out += [ln, '         1        10']
        k += 2
        continue
    out.append(ln)
    k += 1
out.append('*ELEMENT_SOLID')
eid = 0
ne = len(elems)
for e, (_, n) in enumerate(elems):
    q = 4 if a.kind == 'tet' else min(4 * e // ne, 3)
    if a.kind == 'tet' or q == 2:
        for t in KUHN:
            eid += 1
            c = [n[j - 1] for j in t]
            out += ['%8d%8d' % (eid, 3 if a.kind == 'mixed' else 1),
                    ''.join('%8d' % v for v in c + [c[3]] * 4)]
    elif q == 0:
        eid += 1
        out += ['%8d%8d' % (eid, 1), ''.join('%8d' % v for v in n)]
    elif q == 1:
        for w in WEDGES:
            eid += 1
            out += ['%8d%8d' % (eid, 2), ''.join('%8d' % n[j - 1] for j in w)]
    else:
        for t in KUHN:
            eid += 1
            c = [n[j - 1] for j in t]
            out += ['%8d%8d' % (eid, 4), ''.join('%8d' % v for v in c[:3] + [c[2]] + [c[3]] * 4)]
out += tail
open(a.out, 'w').write('\n'.join(out))
