#!/usr/bin/env python3
"""Benchmark deck: an elastic-plastic steel cube of n x n x n one-point hex8 elements
(*MAT_PIECEWISE_LINEAR_PLASTICITY), its face z = 0 on a stonewall, the body moving at
-50 m/s in z. Units mm, ms, kg, GPa. Runs a fixed number of cycles (ENDCYC).
Usage: gen_cube_deck.py n ncycles out.k"""
import sys
n, ncyc, out = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
h = 10.0 / n
nid = lambda i, j, k: 1 + i + (n + 1) * (j + (n + 1) * k)
with open(out, 'w') as f:
    w = f.write
    w('*KEYWORD\n*TITLE\nbenchmark cube n=%d\n' % n)
    w('*CONTROL_TERMINATION\n%10.4f%10d\n' % (1.0, ncyc))
    w('*CONTROL_TIMESTEP\n       0.0       0.9\n')
    w('*PART\ncube\n         1         1         1\n*SECTION_SOLID\n         1         1\n')
    w('*MAT_PIECEWISE_LINEAR_PLASTICITY\n         1    7.8E-6     210.0       0.3      0.25       1.0\n\n\n\n')
    w('*NODE\n')
    for k in range(n + 1):
        for j in range(n + 1):
            for i in range(n + 1):
                w('%8d%16.6f%16.6f%16.6f\n' % (nid(i, j, k), i * h, j * h, k * h))
    w('*ELEMENT_SOLID\n')
    e = 0
    for k in range(n):
        for j in range(n):
            for i in range(n):
                e += 1
                w('%8d%8d' % (e, 1) + ''.join('%8d' % m for m in (
                    nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k),
                    nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1),
                    nid(i, j + 1, k + 1))) + '\n')
    w('*INITIAL_VELOCITY\n         0\n       0.0       0.0     -50.0\n')
    w('*RIGIDWALL_PLANAR\n         0\n       0.0       0.0       0.0       0.0       0.0       1.0\n')
    w('*END\n')
