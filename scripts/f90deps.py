#!/usr/bin/env python3
"""Write make dependencies for Fortran sources: object -> objects of the modules it uses.
Usage: f90deps.py SRC... > deps.mk   (rules use $(OBJ) so the file serves every build dir)"""
import os, re, sys

mod_re = re.compile(r'^\s*module\s+(?!procedure\b)(\w+)', re.I)
sub_re = re.compile(r'^\s*submodule\s*\(\s*(\w+)', re.I)
use_re = re.compile(r'^\s*use\s*(?:,\s*(intrinsic|non_intrinsic)\s*)?(?:::)?\s*(\w+)', re.I)

provides, uses = {}, {}
for path in sys.argv[1:]:
    stem = os.path.splitext(os.path.basename(path))[0]
    uses[stem] = set()
    with open(path, encoding='utf-8', errors='replace') as f:
        for line in f:
            line = line.split('!')[0]
            m = mod_re.match(line)
            if m:
                provides[m.group(1).lower()] = stem
            m = sub_re.match(line)
            if m:
                uses[stem].add(m.group(1).lower())
            m = use_re.match(line)
            if m and (m.group(1) or '').lower() != 'intrinsic':
                uses[stem].add(m.group(2).lower())
for stem in sorted(uses):
    deps = sorted({provides[u] for u in uses[stem] if u in provides and provides[u] != stem})
    if deps:
        print('$(OBJ)/%s.o: %s' % (stem, ' '.join('$(OBJ)/%s.o' % d for d in deps)))
