"""Readers shared by the checks of dynx's outputs (matsum_check.py, sleout_check.py,
spcforc_check.py, shell_check.py, quad2d_check.py, nr2d_check.py): the column files glstat and
nodout, the plot file's datasets (h5dump), and the option loop's closing lines.
"""
import subprocess
import sys

#: nodout columns after time and node: (first, last + 1) of each 3-vector
NODOUT = {'disp': (2, 5), 'vel': (5, 8), 'acc': (8, 11), 'coor': (11, 14)}


def is_row(line):
    """A data row of a column file: its first word is a number (header lines start with '#',
    or, the names line in gnuplot's columnhead form, with a name)."""
    return line.lstrip()[:1] in tuple('+-.0123456789')


def read_columns(path, node=None):
    """Rows of a column file (glstat, nodout) keyed by time (first column), each a dict column
    name -> value; with node, only the rows whose second column is that node. The names are
    the last header line before the data: '# time ...' or, gnuplot's columnhead form, the
    line 'time ...' without '#' (docs/output-format.md)."""
    cols, rows = None, {}
    for line in open(path):
        if not is_row(line):
            if line.strip():
                cols = line.lstrip('#').split()
            continue
        w = line.split()
        if node is None or int(w[1]) == node:
            rows[float(w[0])] = dict(zip(cols, [float(x) for x in w]))
    return rows


def read_table(path):
    """The number rows of a column file, in file order, each a list of floats."""
    rows = []
    for line in open(path):
        if not is_row(line):
            continue
        rows.append([float(v) for v in line.split()])
    return rows


def nodout_series(out, *fields):
    """{node: [(t, field1, field2, ...)]} from OUT/nodout, each field a 3-list named in
    NODOUT ('disp', 'vel', 'acc', 'coor'), in file order."""
    d = {}
    for r in read_table(out + '/nodout'):
        d.setdefault(int(r[1]), []).append(
            (r[0],) + tuple(r[NODOUT[f][0]:NODOUT[f][1]] for f in fields))
    return d


def h5_dataset(path, name):
    """Dataset name of the HDF5 file path as a flat list of floats (h5dump, 17 digits)."""
    txt = subprocess.run(['h5dump', '-m', '%.17g', '-d', name, path], capture_output=True,
                         text=True, check=True).stdout
    body = txt[txt.index('DATA {') + 6:]
    body = body[:body.index('}')]
    vals = []
    for line in body.splitlines():
        if ':' in line:
            line = line.split(':', 1)[1]
        vals += [float(v) for v in line.replace(',', ' ').split()]
    return vals


def h5_last_state(path):
    """The name of the last plot state under /states of the HDF5 file path."""
    txt = subprocess.run(['h5ls', path + '/states'], capture_output=True, text=True,
                         check=True).stdout
    return sorted(w for w in (line.split()[0] for line in txt.splitlines() if line.strip())
                  if w.isdigit())[-1]


def unknown_option(opt):
    """An option the check does not know: say so and exit 2."""
    print('unknown option ' + opt)
    sys.exit(2)
