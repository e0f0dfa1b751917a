#!/usr/bin/env python3
# Module-level save variables in src/ per file (one per declared name), for issue 14's count:
#   python3 scripts/count_save.py
import re, sys, glob, collections
# module-level save variables: declarations with the save attribute (one per name)
tot = collections.Counter()
for f in sorted(glob.glob('src/**/*.f90', recursive=True)):
    for line in open(f):
        s = line.split('!')[0]
        if '::' not in s or not re.search(r',\s*save\b', s.split('::')[0], re.I):
            continue
        rhs = s.split('::', 1)[1]
        depth, n = 0, 1
        for ch in rhs:
            if ch in '([': depth += 1
            elif ch in ')]': depth -= 1
            elif ch == ',' and depth == 0: n += 1
        tot[f] += n
for f, n in sorted(tot.items()): print(f'{n:4d} {f}')
print(f'{sum(tot.values()):4d} total')
