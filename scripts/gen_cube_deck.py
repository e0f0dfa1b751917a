#!/usr/bin/env python3
"""Benchmark deck: an elastic-plastic steel cube of n x n x n one-point hex8 elements
(*MAT_PIECEWISE_LINEAR_PLASTICITY), its face z = 0 on a stonewall, the body moving at
-50 m/s in z. Units mm, ms, kg, GPa. Runs a fixed number of cycles (ENDCYC).
Usage: gen_cube_deck.py n ncycles out.k"""
import sys
from dxmesh import box_cards
n, ncyc, out = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
h = 10.0 / n
with open(out, 'w') as f:
    w = f.write
    w('*KEYWORD\n*TITLE\nbenchmark cube n=%d\n' % n)
    w('*CONTROL_TERMINATION\n%10.4f%10d\n' % (1.0, ncyc))
    w('*CONTROL_TIMESTEP\n       0.0       0.9\n')
    w('*PART\ncube\n         1         1         1\n*SECTION_SOLID\n         1         1\n')
    w('*MAT_PIECEWISE_LINEAR_PLASTICITY\n         1    7.8E-6     210.0       0.3      0.25       1.0\n\n\n\n')
    for line in box_cards(n, n, n, h, h, h):
        w(line)
    w('*INITIAL_VELOCITY\n         0\n       0.0       0.0     -50.0\n')
    w('*RIGIDWALL_PLANAR\n         0\n       0.0       0.0       0.0       0.0       0.0       1.0\n')
    w('*END\n')
