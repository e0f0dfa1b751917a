"""Readers shared by the checks of dynx's ASCII outputs (matsum_check.py, sleout_check.py,
spcforc_check.py): the column files glstat and nodout, and the option loop's closing lines.
"""
import sys


def read_columns(path, node=None):
    """Rows of a '#'-headed column file (glstat, nodout) keyed by time (first column), each a
    dict column name -> value; with node, only the rows whose second column is that node."""
    cols, rows = None, {}
    for line in open(path):
        if line.startswith('#'):
            cols = line[1:].split()
            continue
        w = line.split()
        if node is None or int(w[1]) == node:
            rows[float(w[0])] = dict(zip(cols, [float(x) for x in w]))
    return rows


def unknown_option(opt):
    """An option the check does not know: say so and exit 2."""
    print('unknown option ' + opt)
    sys.exit(2)
