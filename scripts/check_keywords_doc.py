#!/usr/bin/python3
"""Check that docs/keywords.md lists every keyword dynx reads, and nothing else.

  scripts/check_keywords_doc.py          compare; exit 1 on a difference, printing it
  scripts/check_keywords_doc.py --list   print the keywords dynx reads, one per line

The keywords dynx reads are
  - the registry (src/deck/dx_deck_registry.f90): every `reg%add('NAME', ...)` in src/deck/,
    plus the rows of the material and EOS registry (src/materials/dx_mat_factory.f90,
    mat_row/eos_row) that register_materials (src/deck/dx_read_materials.f90) adds with their
    numeric alias (*MAT_001, *EOS_004; dynx's own models, type 900 and up, have none);
    *MAT_RIGID (generic = .false.) registers itself;
  - the deck-structure keywords the card reader handles itself (src/deck/dx_deck_cards.f90):
    KEYWORD, TITLE, INCLUDE, PARAMETER, END (each must still appear there as 'NAME').

The document side is the table under the heading "## Keyword index" in docs/keywords.md:
one row per keyword (or per keyword and its aliases); the first cell names one or more keywords
as `*NAME`. Every keyword dynx reads must be named in a row, and every keyword named in a row
must be one dynx reads. A `reg%add(` whose name the script cannot parse is an error, so the
check cannot silently pass over a new form of registration.

The generated reference docs/manual/keywords.md (bin/dynx-keywords: every keyword of the
registry read by its own reader from blank cards, the fields it takes with their defaults)
must equal the program's output byte for byte, and name exactly the keywords above (without
the deck-structure ones). Regenerate it with
  bin/dynx-keywords -o docs/manual/keywords.md
(scripts/check_keywords_doc.py --update does that). Without bin/dynx-keywords: a failure
("make all" builds it).
"""
import os
import re
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
DECK = os.path.join(ROOT, 'src', 'deck')
FACTORY = os.path.join(ROOT, 'src', 'materials', 'dx_mat_factory.f90')
DOC = os.path.join(ROOT, 'docs', 'keywords.md')
GEN_DOC = os.path.join(ROOT, 'docs', 'manual', 'keywords.md')
GEN_TOOL = os.path.join(ROOT, 'bin', 'dynx-keywords')
STRUCTURE = ['KEYWORD', 'TITLE', 'INCLUDE', 'INCLUDE_PATH', 'INCLUDE_PATH_RELATIVE', 'PARAMETER',
             'PARAMETER_EXPRESSION', 'PARAMETER_DUPLICATION', 'END']
# the dynamic registrations of register_materials (dx_read_materials.f90), read from the
# material/EOS registry below
DYNAMIC = ["trim(t(i)%keyword)", "'MAT_'//num", "'EOS_'//num"]


def param_array(text, name):
    """The strings of a character parameter array NAME(...) = [character(...) :: 'A', ...]."""
    m = re.search(r'\b%s\s*\([^)]*\)\s*=\s*\[(.*?)\]' % re.escape(name), text, re.S)
    if not m:
        return None
    return re.findall(r"'([A-Z0-9_]+)'", m.group(1))


def strip_comment(line):
    out, q = [], None
    for ch in line:
        if q:
            if ch == q:
                q = None
        elif ch in "'\"":
            q = ch
        elif ch == '!':
            break
        out.append(ch)
    return ''.join(out)


def registered():
    """The keywords dynx reads, and a list of problems met while collecting them."""
    names, problems = set(), []
    for fn in sorted(os.listdir(DECK)):
        if not fn.endswith('.f90'):
            continue
        path = os.path.join(DECK, fn)
        with open(path) as f:
            text = f.read()
        for no, line in enumerate(text.split('\n'), 1):
                code = strip_comment(line)
                m = re.search(r'\breg%add\(\s*(.*)$', code)    # the registry (registry_t)
                if not m or fn == 'dx_deck_registry.f90':
                    continue
                arg = m.group(1)
                lit = re.match(r"'([A-Z0-9_]+)'\s*,", arg)
                # 'PREFIX_'//trim(TABLE(i)): one keyword per string of the parameter TABLE
                tab = re.match(r"'([A-Z0-9_]*)'\s*//\s*trim\(\s*(\w+)\(\w+\)\s*\)\s*,", arg)
                items = param_array(text, tab.group(2)) if tab else None
                if lit:
                    names.add(lit.group(1))
                elif items:
                    names.update(tab.group(1) + x for x in items)
                elif not any(arg.startswith(d) for d in DYNAMIC):
                    problems.append('%s:%d: cannot read the keyword name of: %s'
                                    % (os.path.relpath(path, ROOT), no, code.strip()))
    with open(FACTORY) as f:
        text = f.read()
    rows = re.findall(r"\b(mat|eos)_row\(\s*'([A-Z0-9_]+)'\s*,\s*(\d+)\s*,\s*\d+\s*(?:,\s*\.(true|false)\.)?",
                      text)
    if not rows:
        problems.append('%s: no mat_row/eos_row found' % os.path.relpath(FACTORY, ROOT))
    for kind, name, num, generic in rows:
        if kind == 'mat' and generic == 'false':
            continue        # registers itself with its own reader (found above)
        names.add(name)
        if kind == 'mat' and int(num) >= 900:
            continue        # dynx's own models (*DYNX_...): no *MAT_nnn alias
        names.add('%s_%03d' % ('MAT' if kind == 'mat' else 'EOS', int(num)))
    with open(os.path.join(DECK, 'dx_deck_cards.f90')) as f:
        cards = f.read()
    for name in STRUCTURE:
        if "'%s'" % name in cards:
            names.add(name)
        else:
            problems.append("src/deck/dx_deck_cards.f90: '%s' no longer handled by the card "
                            "reader: update STRUCTURE in scripts/check_keywords_doc.py" % name)
    return names, problems


def documented():
    """Keywords named in the first cell of the rows of the "## Keyword index" table."""
    names, rows, inside = {}, 0, False
    with open(DOC) as f:
        for no, line in enumerate(f, 1):
            if line.startswith('## '):
                inside = line.startswith('## Keyword index')
                continue
            if not inside or not line.startswith('|'):
                continue
            first = line.split('|')[1]
            if set(first.strip()) <= set('-: '):
                continue
            found = re.findall(r'`\*([A-Z0-9_]+)`', first)
            if not found:
                continue        # the header row
            rows += 1
            for name in found:
                names.setdefault(name, no)
    return names, rows


def generated(reg, problems):
    """Compare docs/manual/keywords.md with bin/dynx-keywords' output (--update: write it)."""
    import subprocess
    if not os.access(GEN_TOOL, os.X_OK):
        problems.append('bin/dynx-keywords not built (make all): the generated reference '
                        'docs/manual/keywords.md cannot be checked')
        return
    out = subprocess.run([GEN_TOOL], capture_output=True, text=True, timeout=60)
    if out.returncode != 0:
        problems.append('bin/dynx-keywords failed (exit %d): %s' % (out.returncode, out.stderr))
        return
    if '--update' in sys.argv[1:]:
        with open(GEN_DOC, 'w') as f:
            f.write(out.stdout)
    names = set(re.findall(r'^## \*([A-Z0-9_]+)', out.stdout, re.M))
    for name in sorted(reg - set(STRUCTURE) - names):
        problems.append('bin/dynx-keywords: *%s is registered but not in the generated '
                        'reference' % name)
    for name in sorted(names - reg):
        problems.append('bin/dynx-keywords: *%s is in the generated reference but not found '
                        'in the registry sources' % name)
    try:
        with open(GEN_DOC) as f:
            doc = f.read()
    except OSError:
        doc = ''
    if doc != out.stdout:
        a, b = doc.splitlines(), out.stdout.splitlines()
        k = next((i for i in range(min(len(a), len(b))) if a[i] != b[i]), min(len(a), len(b)))
        problems.append('docs/manual/keywords.md:%d differs from bin/dynx-keywords (the reader '
                        'changed; regenerate: scripts/check_keywords_doc.py --update): %r vs %r'
                        % (k + 1, a[k] if k < len(a) else '<end>', b[k] if k < len(b) else '<end>'))


def main():
    reg, problems = registered()
    if '--list' in sys.argv[1:]:
        print('\n'.join(sorted(reg)))
        return 0
    generated(reg, problems)
    doc, rows = documented()
    if rows == 0:
        problems.append('docs/keywords.md: no "## Keyword index" table with `*KEYWORD` rows')
    for name in sorted(reg - set(doc)):
        problems.append('docs/keywords.md: keyword *%s is read by dynx but has no row in the '
                        'Keyword index' % name)
    for name in sorted(set(doc) - reg):
        problems.append('docs/keywords.md:%d: *%s has a row in the Keyword index but dynx does not '
                        'read it (not in the registry)' % (doc[name], name))
    for p in problems:
        print(p)
    print('keywords: %d read by dynx, %d named in %d rows of docs/keywords.md'
          % (len(reg), len(doc), rows))
    fail = 1 if problems else 0
    print('%d passed, %d failed' % (1 - fail, fail))
    return fail


if __name__ == '__main__':
    sys.exit(main())
