#!/usr/bin/python3
"""Layering check and seam counts for dynx (the rules of shared/docs/architecture.md).

  scripts/check_layers.py            list every `use` that crosses the layering; exit 1 if one
                                     is not in scripts/layers_allowed.txt (the ratchet: known
                                     crossings still to remove; a new crossing fails make test)
  scripts/check_layers.py --counts   print the seam counts that docs/design.md reports
  scripts/check_layers.py --write-allowed   rewrite scripts/layers_allowed.txt from the tree
  scripts/check_layers.py --update-doc      write the counts into docs/design.md

A module's layer is the folder under src/ that holds its file (src/materials/eos counts as
materials). `use` of a module in the same folder is always allowed. Intrinsic modules are
ignored, except that mpi_f08 may be used only in src/parallel/ and hdf5 only in
src/io/dx_h5*.f90 (dx_h5: datasets, dx_h5_file: files and attributes), and fftw3.f03 may be
included only by src/tools/dx_fft.f90.
"""
import os
import re
import subprocess
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
SRC = os.path.join(ROOT, 'src')
ALLOWED_FILE = os.path.join(ROOT, 'scripts', 'layers_allowed.txt')

# who may use whom (architecture.md, "Layering"); main and tools sit on top and may use all
RULES = {
    'solvers': {'engine', 'linalg', 'io', 'model', 'base'},
    'engine': {'elements', 'materials', 'contact', 'rigid', 'loads', 'io', 'parallel', 'model',
               'linalg', 'base'},
    'build': {'elements', 'materials', 'contact', 'rigid', 'loads', 'model', 'linalg', 'base'},
    'deck': {'model', 'materials', 'base'},
    'elements': {'materials', 'model', 'linalg', 'base'},
    'contact': {'model', 'linalg', 'base'},
    'rigid': {'model', 'linalg', 'base'},
    'loads': {'model', 'linalg', 'base'},
    'materials': {'linalg', 'base'},
    'io': {'model', 'parallel', 'base'},
    'parallel': {'base'},
    'linalg': {'base'},
    'base': set(),
}
TOP = {'main', 'tools'}
INTRINSIC = {'iso_fortran_env', 'iso_c_binding', 'ieee_arithmetic', 'ieee_exceptions',
             'ieee_features', 'omp_lib'}

FFTW_USER = 'src/tools/dx_fft.f90'
INCLUDE_FFTW_RE = re.compile(r'''^\s*include\s*['"]fftw3''', re.I)
USE_RE = re.compile(r'^\s*use\s*(?:,\s*(intrinsic|non_intrinsic)\s*)?(?:::)?\s*(\w+)', re.I)
MOD_RE = re.compile(r'^\s*module\s+(\w+)\s*(?:!.*)?$', re.I)


def layer_of(path):
    rel = os.path.relpath(path, SRC).split(os.sep)
    return rel[0]


def sources():
    out = []
    for dirpath, _, files in os.walk(SRC):
        for f in sorted(files):
            if f.endswith('.f90'):
                out.append(os.path.join(dirpath, f))
    return sorted(out)


def scan():
    """(module -> layer, list of (file, line, layer, used module))."""
    mods, uses = {}, []
    for path in sources():
        with open(path, encoding='utf-8', errors='replace') as fh:
            lines = fh.readlines()
        for i, line in enumerate(lines, 1):
            code = line.split('!', 1)[0]
            m = MOD_RE.match(code)
            if m and m.group(1).lower() != 'procedure':
                mods[m.group(1).lower()] = layer_of(path)
            u = USE_RE.match(code)
            if u:
                uses.append((os.path.relpath(path, ROOT), i, layer_of(path), u.group(2).lower(),
                             (u.group(1) or '').lower() == 'intrinsic'))
    return mods, uses


def model_may_use(name, mods):
    # model -> base, the abstract material and equation-of-state types (the model holds
    # class(material_t) and class(eos_t)) and the physics folders' *_types modules
    return name in ('dx_material', 'dx_eos') or name.endswith('_types') or \
        mods.get(name) == 'base'


def crossings():
    mods, uses = scan()
    bad, h5users = [], set()
    for path, line, layer, name, intrinsic in uses:
        if name == 'mpi_f08':
            if layer != 'parallel':
                bad.append((path, line, name, 'mpi_f08 outside src/parallel'))
            continue
        if name == 'hdf5':
            if not re.match(r'src/io/dx_h5[^/]*\.f90$', path):
                h5users.add(path)
            continue
        if intrinsic or name in INTRINSIC or name not in mods:
            continue
        target = mods[name]
        if target == layer or layer in TOP:
            continue
        if layer == 'model':
            ok = model_may_use(name, mods)
        else:
            ok = target in RULES.get(layer, set())
        if not ok:
            bad.append((path, line, name, '%s -> %s' % (layer, target)))
    for p in sorted(h5users):
        bad.append((p, 0, 'hdf5', 'hdf5 outside src/io/dx_h5*.f90'))
    # FFTW: one module includes fftw3.f03 (only bin/dynx-thist links -lfftw3)
    for path in sources():
        rel = os.path.relpath(path, ROOT)
        if rel == FFTW_USER:
            continue
        with open(path, encoding='utf-8', errors='replace') as fh:
            for i, line in enumerate(fh, 1):
                if INCLUDE_FFTW_RE.match(line.split('!', 1)[0]):
                    bad.append((rel, i, 'fftw3', 'fftw3.f03 outside ' + FFTW_USER))
    return bad


def key(c):
    return '%s uses %s (%s)' % (c[0], c[2], c[3])


def folder_cycles():
    mods, uses = scan()
    edges = set()
    for _, _, layer, name, _ in uses:
        t = mods.get(name)
        if t and t != layer:
            edges.add((layer, t))
    return sorted({tuple(sorted(e)) for e in edges if (e[1], e[0]) in edges})


def count_lines(path):
    with open(path, encoding='utf-8', errors='replace') as fh:
        return sum(1 for _ in fh)


def counts(out=print):
    """The seam counts docs/design.md reports, each with the rule that produces it."""
    srcs = sources()
    big = [(os.path.relpath(p, ROOT), count_lines(p)) for p in srcs if count_lines(p) > 800]
    main = os.path.join(SRC, 'main', 'dynx.f90')
    par_if = 0
    sdir = os.path.join(SRC, 'solvers')
    # an if-test on a parallel flag or the rank count: par, par_on(), par_engine_on(),
    # par_size(), nprocs (the words the code uses for them)
    par_re = re.compile(r'\bif\s*\(.*\b(par|par_\w*on|par_size|par_active|nprocs)\b', re.I)
    for p in srcs:
        if p.startswith(sdir + os.sep):
            with open(p, encoding='utf-8', errors='replace') as fh:
                par_if += sum(1 for l in fh if par_re.search(l.split('!', 1)[0]))
    # hexahedron facts: the words hex/hex8 in code (checksum_hex and %hex() are hexadecimal)
    hex_re = re.compile(r'(?<![%_\w])hex(8|_|\b)(?!\s*(\(|=>))', re.I)
    hexfiles = []
    edir = os.path.join(SRC, 'elements')
    for p in srcs:
        if p.startswith(edir + os.sep):
            continue
        with open(p, encoding='utf-8', errors='replace') as fh:
            if any(hex_re.search(l.split('!', 1)[0]) for l in fh):
                hexfiles.append(os.path.relpath(p, ROOT))
    save_re = re.compile(r'^\s*(?:[^!]*,\s*save\b|save\s*(?:::|$))', re.I)
    saves = {}
    for p in srcs:
        inproc = 0
        with open(p, encoding='utf-8', errors='replace') as fh:
            for l in fh:
                code = l.split('!', 1)[0]
                if re.match(r'^\s*(contains)\b', code, re.I):
                    inproc = 1
                if not inproc and save_re.match(code):
                    rel = os.path.relpath(p, ROOT)
                    saves[rel] = saves.get(rel, 0) + 1
    dup = '?'
    try:
        r = subprocess.run(['duplicates', '--repo', SRC, '--seconds', '120'],
                           capture_output=True, text=True, timeout=300)
        m = re.search(r'^(\d+) pairs of places', r.stdout, re.M)
        dup = m.group(1) if m else ('0' if 'no pairs' in r.stdout.lower() else '?')
    except (OSError, subprocess.SubprocessError):
        pass
    out('modules over 800 lines: %d %s' % (len(big), ' '.join('%s(%d)' % b for b in big)))
    out('main program lines: %d' % count_lines(main))
    out('if-tests on the rank count or a parallel flag in src/solvers: %d' % par_if)
    out('files outside src/elements naming hex/hex8: %d %s' % (len(hexfiles), ' '.join(hexfiles)))
    out('module save variables (declarations before contains): %d in %d modules %s' % (
        sum(saves.values()), len(saves), ' '.join('%s(%d)' % kv for kv in sorted(saves.items()))))
    out('folder pairs that import each other: %d %s' % (
        len(folder_cycles()), ' '.join('%s<->%s' % c for c in folder_cycles())))
    out('use statements crossing the layering: %d' % len({key(c) for c in crossings()}))
    out('duplicates pairs in src (duplicates --repo src): %s' % dup)


BEGIN, END = '<!-- counts: scripts/check_layers.py --update-doc -->', '<!-- /counts -->'


def update_doc(path):
    """Rewrite the counts block of docs/design.md (between BEGIN and END) from the tree."""
    lines = []
    counts(lambda l: lines.append('- ' + l))
    with open(path) as fh:
        text = fh.read()
    if BEGIN not in text or END not in text:
        print('check_layers: %s has no counts block (%s ... %s)' % (path, BEGIN, END))
        return 1
    head, rest = text.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    with open(path + '.tmp', 'w') as fh:
        fh.write(head + BEGIN + '\n' + '\n'.join(lines) + '\n' + END + tail)
    os.replace(path + '.tmp', path)
    print('check_layers: counts written to %s' % path)
    return 0


def main():
    if '--counts' in sys.argv:
        counts()
        return 0
    if '--update-doc' in sys.argv:
        return update_doc(os.path.join(ROOT, 'docs', 'design.md'))
    bad = crossings()
    keys = sorted({key(c) for c in bad})
    if '--write-allowed' in sys.argv:
        with open(ALLOWED_FILE + '.tmp', 'w') as fh:
            fh.write('# use statements that still cross the layering (scripts/check_layers.py);\n'
                     '# the list only shrinks: a new crossing fails make test\n')
            fh.writelines(k + '\n' for k in keys)
        os.replace(ALLOWED_FILE + '.tmp', ALLOWED_FILE)
        print('check_layers: %d known crossings written to %s' % (len(keys), ALLOWED_FILE))
        return 0
    allowed = set()
    if os.path.exists(ALLOWED_FILE):
        with open(ALLOWED_FILE) as fh:
            allowed = {l.strip() for l in fh if l.strip() and not l.startswith('#')}
    new = [k for k in keys if k not in allowed]
    gone = sorted(allowed - set(keys))
    for k in new:
        print('FAIL layering: ' + k)
    if gone:
        print('check_layers: %d listed crossings are gone; shrink the list with '
              'scripts/check_layers.py --write-allowed' % len(gone))
    print('check_layers: %d crossings (%d known, %d new), %d folder pairs import each other' % (
        len(keys), len(keys) - len(new), len(new), len(folder_cycles())))
    return 1 if new else 0


if __name__ == '__main__':
    sys.exit(main())
