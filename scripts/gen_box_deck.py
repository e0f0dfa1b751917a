#!/usr/bin/env python3
"""Box mesh deck for the partitioner and scaling studies: nx x ny x nz one-point hex8
elements (ELFORM 1) of *MAT_ELASTIC steel in a 1 x 1 x 1 (nx/nz, ny/nz scaled) block,
face z = 0 held by *BOUNDARY_SPC_SET, the body moving at 10 m/s in z; a fixed number
of cycles (ENDCYC). Units mm, ms, kg, GPa. Default 50 x 50 x 40 = 100 000 elements.
Usage: gen_box_deck.py out.k [nx ny nz [ncycles]]"""
import sys
from dxmesh import box_cards, node_list_cards, bottom_ids
out = sys.argv[1]
nx, ny, nz = (int(a) for a in sys.argv[2:5]) if len(sys.argv) >= 5 else (50, 50, 40)
ncyc = int(sys.argv[5]) if len(sys.argv) >= 6 else 100
h = 1.0
with open(out, 'w') as f:
    w = f.write
    w('*KEYWORD\n*TITLE\nbox %d x %d x %d hex8\n' % (nx, ny, nz))
    w('*CONTROL_TERMINATION\n%10.4f%10d\n' % (1.0, ncyc))
    w('*CONTROL_TIMESTEP\n       0.0       0.9\n')
    w('*PART\nbox\n         1         1         1\n*SECTION_SOLID\n         1         1\n')
    w('*MAT_ELASTIC\n         1    7.8E-6     210.0       0.3\n')
    for line in box_cards(nx, ny, nz, h, h, h):
        w(line)
    for line in node_list_cards(1, bottom_ids(nx, ny)):
        w(line)
    w('*BOUNDARY_SPC_SET\n         1         0         1         1         1         0         0         0\n')
    w('*INITIAL_VELOCITY\n         0\n       0.0       0.0      10.0\n')
    w('*END\n')
