#!/usr/bin/env python3
"""Checks of the seed's shell scenes (scripts/gen_shell_scenes.py; decks/shell_projectile_plate,
decks/shell_box_post). Python standard library only (d3plot.h5 through scripts/dxpost.py).

  shell_scene_check.py sample OUTDIR MESH            the sampled quantities of one run
  shell_scene_check.py agree MESH REF OUT... --tol-disp D --tol-vel V --tol-vm S
      each OUT against REF: the largest difference over the run of the sampled nodes'
      displacement magnitude and velocity magnitude (nodout, interpolated onto REF's times)
      and of the von Mises stress of the sampled elements (d3plot states); fails when one
      passes its bound. --mesh-out MESH2: the OUTs are runs of another mesh (the sampled
      points paired by their place in the history list: a mesh-refinement difference)
  shell_scene_check.py order MESH REF OUT1 OUT2 ...
      the largest differences to REF (as agree) do not decrease from OUT1 to OUT2 ... for
      each of the three quantities (the accuracy order of the lamina algorithms)
  shell_scene_check.py thickness OUTDIR T0 TOL       the last state's shell thickness field:
      uniform within TOL (relative) and below the initial T0
  shell_scene_check.py energy OUTDIR TOL             max |energy ratio - 1| over glstat <= TOL
  shell_scene_check.py value OUTDIR NODE COLUMN TIME EXPECT TOL
      nodout COLUMN of NODE interpolated at TIME within TOL of EXPECT
  shell_scene_check.py peak OUTDIR NODE COLUMN EXPECT TOL   the smallest value (a peak
      deflection: negative) of COLUMN of NODE within TOL of EXPECT
The sampled nodes are the deck's *DATABASE_HISTORY_NODE list but its last (the projectile or
the vehicle mass); the sampled elements are, for each sampled node, the part-1 shell of
smallest id that holds it."""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import dxpost  # noqa: E402


def read_mesh(path):
    """(history nodes, {element id: (part, nodes)}) of a generated mesh.k"""
    hist, elems, kw = [], {}, ''
    for line in open(path):
        if line.startswith('$'):
            continue
        if line.startswith('*'):
            kw = line.strip()
            continue
        if kw == '*DATABASE_HISTORY_NODE':
            hist += [int(line[k:k + 10]) for k in range(0, len(line.rstrip()), 10)]
        elif kw == '*ELEMENT_SHELL':
            v = [int(line[k:k + 8]) for k in range(0, 48, 8)]
            elems[v[0]] = (v[1], v[2:])
    return hist, elems


def samples(mesh):
    hist, elems = read_mesh(mesh)
    nodes = [n for n in hist[:-1] if n > 0]
    els = []
    for n in nodes:
        els.append(min(e for e, (p, c) in elems.items() if p == 1 and n in c))
    return nodes, els


def nodout(outdir):
    names, rows = dxpost.columns(os.path.join(outdir, 'nodout'))
    series = {}
    for r in rows:
        series.setdefault(int(r[1]), []).append(r)
    return names, series


def interp(ts, ys, t):
    if t <= ts[0]:
        return ys[0]
    for k in range(1, len(ts)):
        if t <= ts[k]:
            a = (t - ts[k - 1])/(ts[k] - ts[k - 1]) if ts[k] > ts[k - 1] else 1.0
            return ys[k - 1] + a*(ys[k] - ys[k - 1])
    return ys[-1]


def vm_series(outdir, els):
    """(times, {element: [von Mises per state]}) from d3plot.h5"""
    h5 = os.path.join(outdir, 'd3plot.h5')
    times = dxpost.states(h5)
    _, ids = dxpost.dataset(h5, '/mesh/element_ids')
    pos = {int(e): k for k, e in enumerate(ids)}
    out = {e: [] for e in els}
    for k in range(len(times)):
        _, vm = dxpost.dataset(h5, dxpost.state_path(k + 1) + '/von_mises')
        for e in els:
            out[e].append(vm[pos[e]])
    return list(times), out


def node_mag(names, rows, what):
    c = [names.index(f'{a}_{what}') for a in 'xyz']
    return [r[0] for r in rows], [math.sqrt(sum(r[k]**2 for k in c)) for r in rows]


def cmd_sample(outdir, mesh):
    nodes, els = samples(mesh)
    names, ser = nodout(outdir)
    for n in nodes:
        _, d = node_mag(names, ser[n], 'disp')
        _, v = node_mag(names, ser[n], 'vel')
        print(f'node {n}: largest |u| {max(d):.5g} mm, largest |v| {max(v):.5g} mm/ms')
    t, vm = vm_series(outdir, els)
    for e in els:
        print(f'element {e}: largest von Mises {max(vm[e]):.5g} GPa over {len(t)} states')
    return 0


def cmd_agree(mesh, ref, outs, tol, omesh=None, worsts=None):
    worsts = [] if worsts is None else worsts
    nodes, els = samples(mesh)
    onodes, oels = samples(omesh) if omesh else (nodes, els)
    names, rser = nodout(ref)
    rt, rvm = vm_series(ref, els)
    bad = 0
    for out in outs:
        onames, oser = nodout(out)
        worst = {'disp': 0.0, 'vel': 0.0, 'vm': 0.0}
        where = {}
        for n, no in zip(nodes, onodes):
            for what in ('disp', 'vel'):
                ts, ys = node_mag(names, rser[n], what)
                to, yo = node_mag(onames, oser[no], what)
                for t, y in zip(ts, ys):
                    d = abs(interp(to, yo, t) - y)
                    if d > worst[what]:
                        worst[what], where[what] = d, f'node {n}, t {t:.4g}'
        ot, ovm = vm_series(out, oels)
        for e, eo in zip(els, oels):
            for t, y in zip(rt, rvm[e]):
                d = abs(interp(ot, ovm[eo], t) - y)
                if d > worst['vm']:
                    worst['vm'], where['vm'] = d, f'element {e}, t {t:.4g}'
        for what, unit in (('disp', 'mm'), ('vel', 'mm/ms'), ('vm', 'GPa')):
            ok = worst[what] <= tol.get(what, math.inf)
            bad += not ok
            print(f'{"ok  " if ok else "FAIL"} {out} against {ref}: largest |d {what}| '
                  f'{worst[what]:.4g} {unit} ({where.get(what, "-")}), bound '
                  f'{tol.get(what, math.inf):g}')
        worsts.append(worst)
    return 1 if bad else 0


def cmd_order(mesh, ref, outs):
    """the runs' largest differences to REF grow in the order given, for every quantity"""
    worsts = []
    cmd_agree(mesh, ref, outs, {}, worsts=worsts)
    bad = 0
    for what in ('disp', 'vel', 'vm'):
        v = [w[what] for w in worsts]
        ok = all(v[k] <= v[k + 1] for k in range(len(v) - 1))
        bad += not ok
        print(f'{"ok  " if ok else "FAIL"} order of the {what} differences: ' +
              ' <= '.join(f'{x:.4g}' for x in v))
    return 1 if bad else 0


def cmd_energy(outdir, tol):
    names, rows = dxpost.columns(os.path.join(outdir, 'glstat'))
    k = names.index('energy_ratio')
    worst = max(abs(r[k] - 1.0) for r in rows)
    ok = worst <= tol
    print(f'{"ok  " if ok else "FAIL"} {outdir}: max |energy ratio - 1| {worst:.4g} (bound {tol:g})')
    return 0 if ok else 1


def cmd_value(outdir, node, col, t, expect, tol, peak=False):
    names, ser = nodout(outdir)
    k = names.index(col)
    ts = [r[0] for r in ser[node]]
    ys = [r[k] for r in ser[node]]
    if peak:
        y = min(ys)
        t = ts[ys.index(y)]
    else:
        y = interp(ts, ys, t)
    ok = abs(y - expect) <= tol
    print(f'{"ok  " if ok else "FAIL"} {outdir}: node {node} {col} at t {t:.4g} = {y:.6g} '
          f'(expected {expect:g} +- {tol:g})')
    return 0 if ok else 1


def cmd_thickness(outdir, t0, tol):
    """the last plot state's shell thickness (cells with one): uniform to TOL (relative) and
    below T0 (a stretched membrane thins)"""
    h5 = os.path.join(outdir, 'd3plot.h5')
    n = len(dxpost.states(h5))
    _, t = dxpost.dataset(h5, dxpost.state_path(n) + '/thickness')
    t = [x for x in t if x > 0.0]
    mean = sum(t)/len(t)
    spread = (max(t) - min(t))/mean
    ok = spread <= tol and mean < t0
    print(f'{"ok  " if ok else "FAIL"} {outdir}: {len(t)} shells, thickness {mean:.12g} '
          f'(initial {t0:g}), spread {spread:.3g} (bound {tol:g})')
    return 0 if ok else 1


def main(a):
    if not a:
        raise SystemExit(__doc__)
    if a[0] == 'sample':
        return cmd_sample(a[1], a[2])
    if a[0] == 'agree':
        tol, rest, omesh = {}, [], None
        k = 1
        while k < len(a):
            if a[k] == '--mesh-out':
                omesh = a[k + 1]
                k += 2
            elif a[k].startswith('--tol-'):
                tol[a[k][6:]] = float(a[k + 1])
                k += 2
            else:
                rest.append(a[k])
                k += 1
        return cmd_agree(rest[0], rest[1], rest[2:], tol, omesh)
    if a[0] == 'order':
        return cmd_order(a[1], a[2], a[3:])
    if a[0] == 'energy':
        return cmd_energy(a[1], float(a[2]))
    if a[0] == 'thickness':
        return cmd_thickness(a[1], float(a[2]), float(a[3]))
    if a[0] == 'value':
        return cmd_value(a[1], int(a[2]), a[3], float(a[4]), float(a[5]), float(a[6]))
    if a[0] == 'peak':
        return cmd_value(a[1], int(a[2]), a[3], 0.0, float(a[4]), float(a[5]), peak=True)
    raise SystemExit(__doc__)


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
