#!/usr/bin/env python3
"""Box mesh deck for the partitioner and scaling studies: nx x ny x nz one-point hex8
elements (ELFORM 1) of *MAT_ELASTIC steel in a 1 x 1 x 1 (nx/nz, ny/nz scaled) block,
face z = 0 held by *BOUNDARY_SPC_SET, the body moving at 10 m/s in z; a fixed number
of cycles (ENDCYC). Units mm, ms, kg, GPa. Default 50 x 50 x 40 = 100 000 elements.
Usage: gen_box_deck.py out.k [nx ny nz [ncycles]]"""
import sys
out = sys.argv[1]
nx, ny, nz = (int(a) for a in sys.argv[2:5]) if len(sys.argv) >= 5 else (50, 50, 40)
ncyc = int(sys.argv[5]) if len(sys.argv) >= 6 else 100
h = 1.0
nid = lambda i, j, k: 1 + i + (nx + 1) * (j + (ny + 1) * k)
with open(out, 'w') as f:
    w = f.write
    w('*KEYWORD\n*TITLE\nbox %d x %d x %d hex8\n' % (nx, ny, nz))
    w('*CONTROL_TERMINATION\n%10.4f%10d\n' % (1.0, ncyc))
    w('*CONTROL_TIMESTEP\n       0.0       0.9\n')
    w('*PART\nbox\n         1         1         1\n*SECTION_SOLID\n         1         1\n')
    w('*MAT_ELASTIC\n         1    7.8E-6     210.0       0.3\n')
    w('*NODE\n')
    for k in range(nz + 1):
        for j in range(ny + 1):
            for i in range(nx + 1):
                w('%8d%16.6f%16.6f%16.6f\n' % (nid(i, j, k), i * h, j * h, k * h))
    w('*ELEMENT_SOLID\n')
    e = 0
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                e += 1
                w('%8d%8d' % (e, 1) + ''.join('%8d' % m for m in (
                    nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k),
                    nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1),
                    nid(i, j + 1, k + 1))) + '\n')
    w('*SET_NODE_LIST\n         1\n')
    base = [nid(i, j, 0) for j in range(ny + 1) for i in range(nx + 1)]
    for a in range(0, len(base), 8):
        w(''.join('%10d' % m for m in base[a:a + 8]) + '\n')
    w('*BOUNDARY_SPC_SET\n         1         0         1         1         1         0         0         0\n')
    w('*INITIAL_VELOCITY\n         0\n       0.0       0.0      10.0\n')
    w('*END\n')
