"""Live viewing of a running dynx job in ParaView (issue 21), serial and MPI.

Usage: xvfb-run -a -s "-screen 0 1024x768x24" pvpython scripts/check_live_paraview.py \
           DECK OUTDIR [NP ...]
(NP 1 = the serial bin/dynx; NP > 1 = mpirun --oversubscribe -np NP bin/dynx; the
environment variable DYNX names another binary, e.g. an older build to see the test fail)

ParaView is loaded first, then for each NP the run is started in OUTDIR/live_npN and, as a user
would, its d3plot.xdmf is opened with the XDMF3 reader as soon as it lists 2 states, while the
run goes on. In that ONE session (one reader, never reloaded until step 4):
  1. every time the reader sees is stepped through (UpdatePipeline(t)): each has the whole
     mesh (the point and cell counts of d3plot.h5) and a von Mises range; a PNG is saved;
     the run must still be going when the XDMF is opened (else the deck is too fast: FAIL);
  2. after the run has ended (exit 0), the same times are stepped through again with the same
     reader: each must give the whole mesh and exactly the same von Mises range as during the
     run (the same bytes: the state files the old XDMF names are now links to d3plot.h5); a
     second PNG is saved;
  3. d3plot.states/ holds only links to ../d3plot.h5 and the final XDMF names d3plot.h5;
  4. ReloadFiles (ParaView's "Reload Files"): the reader now sees every state of d3plot.h5
     (its nstates, read with h5dump), and the first ones have the ranges seen live.
With two or more NP: the final von Mises ranges of every state agree between the runs (the
MPI output equals the serial output bit for bit). Exit 0 when all checks pass, 1 otherwise.
"""
import os
import re
import shutil
import subprocess
import sys
import time

from paraview.simple import (Xdmf3ReaderS, GetActiveViewOrCreate, Show, Hide, ColorBy,
                             ResetCamera, Render, SaveScreenshot, ReloadFiles)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
WAIT = 120.0      # seconds to wait for the first 2 states / the end of a run


def xdmf_states(path):
    try:
        return open(path).read().count('<Time Value=')
    except OSError:
        return 0


def h5_nstates(h5):
    out = subprocess.run(["h5dump", "-a", "/nstates", h5], capture_output=True, text=True)
    m = re.search(r"\(0\):\s*(\d+)", out.stdout)
    return int(m.group(1)) if m else None


def h5_mesh_size(h5):
    out = subprocess.run(["h5dump", "-H", "-d", "/mesh/coordinates", "-d", "/mesh/element_ids",
                          h5], capture_output=True, text=True)
    dims = re.findall(r"DATASPACE\s+SIMPLE\s+\{\s*\(\s*(\d+)", out.stdout)
    return (int(dims[0]), int(dims[1])) if len(dims) == 2 else None


def times_of(reader):
    tv = reader.TimestepValues
    if tv is None:
        return []
    if isinstance(tv, float):
        return [tv]
    return list(tv)


def step(reader, times):
    """(points, cells, von Mises range) at each time, read through the reader."""
    seen = []
    for t in times:
        reader.UpdatePipeline(t)
        info = reader.GetDataInformation()
        cd = reader.CellData.keys()
        vm = tuple(reader.CellData["von_mises"].GetRange()) if "von_mises" in cd else None
        seen.append((info.GetNumberOfPoints(), info.GetNumberOfCells(), vm))
    return seen


def snapshot(reader, t, png):
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [640, 480]
    view.ViewTime = t
    disp = Show(reader, view)
    ColorBy(disp, ("CELLS", "von_mises"))
    disp.RescaleTransferFunctionToDataRange(False, True)
    view.CameraPosition = [1.0, -1.0, 0.3]      # the bar (axis z) from the side
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    ResetCamera(view)
    Render(view)
    SaveScreenshot(png, view, ImageResolution=[640, 480])
    Hide(reader, view)
    return os.path.isfile(png) and os.path.getsize(png) > 0


def live_run(deck, out, np, failures):
    """One run watched live; returns the final von Mises ranges of every state."""
    tag = "NP %d" % np
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    cmd = [os.environ.get("DYNX", os.path.join(ROOT, "bin", "dynx")), "-i", deck, "-o", out]
    # pvpython ran MPI_Init itself (Debian's ParaView is built with MPI): its OMPI_/PMIX_
    # variables would make the job's mpirun (or the serial dynx's MPI_Init) join it
    env = {k: v for k, v in os.environ.items()
           if not k.startswith(("OMPI_", "PMIX_", "OPAL_"))}
    if np > 1:
        cmd = ["mpirun", "--oversubscribe", "-np", str(np)] + cmd
        if os.geteuid() == 0:
            env["OMPI_ALLOW_RUN_AS_ROOT"] = "1"
            env["OMPI_ALLOW_RUN_AS_ROOT_CONFIRM"] = "1"
    log = open(os.path.join(out, "..", "live_np%d.stdout" % np), "w")
    t0 = time.time()
    proc = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT, env=env)
    xdmf = os.path.join(out, "d3plot.xdmf")
    while xdmf_states(xdmf) < 2 and proc.poll() is None and time.time() - t0 < WAIT:
        time.sleep(0.05)
    running = proc.poll() is None
    print("%s: XDMF lists %d states at %.1f s, run going: %s"
          % (tag, xdmf_states(xdmf), time.time() - t0, running))
    if not running:
        failures.append("%s: the run ended (exit %s) before the XDMF was opened: the deck "
                        "is too fast for this machine" % (tag, proc.returncode))
    reader = Xdmf3ReaderS(FileName=[xdmf])
    reader.UpdatePipelineInformation()
    live_times = times_of(reader)
    live = step(reader, live_times)
    still = proc.poll() is None
    print("%s: stepped through %d states during the run (still going after: %s)"
          % (tag, len(live_times), still))
    if len(live_times) < 2:
        failures.append("%s: ParaView saw %d states during the run" % (tag, len(live_times)))
    if live_times and not snapshot(reader, live_times[-1], os.path.join(out, "live_during.png")):
        failures.append("%s: no PNG during the run" % tag)
    rc = proc.wait(timeout=WAIT)
    log.close()
    if rc != 0:
        failures.append("%s: the run exited %d" % (tag, rc))
        return []
    h5 = os.path.join(out, "d3plot.h5")
    nst = h5_nstates(h5)
    mesh = h5_mesh_size(h5)
    print("%s: run ended after %.1f s: d3plot.h5 has %s states, mesh (points, cells) %s"
          % (tag, time.time() - t0, nst, mesh))
    for t, (npt, nce, vm) in zip(live_times, live):
        if mesh is None or (npt, nce) != mesh or vm is None:
            failures.append("%s: t=%g read during the run: %d points, %d cells, von Mises %s"
                            % (tag, t, npt, nce, vm))
    # 2. the same session, the same reader, the same times
    after = step(reader, live_times)
    for t, a, b in zip(live_times, live, after):
        if a != b:
            failures.append("%s: t=%g after the end reads %s, during the run %s"
                            % (tag, t, b, a))
    print("%s: stepped again after the end in the same session: %d of %d states equal"
          % (tag, sum(1 for a, b in zip(live, after) if a == b), len(live)))
    if live_times and not snapshot(reader, live_times[-1], os.path.join(out, "live_after.png")):
        failures.append("%s: no PNG after the run" % tag)
    # 3. what the end left on disk
    sdir = os.path.join(out, "d3plot.states")
    bad = [f for f in sorted(os.listdir(sdir)) if not os.path.islink(os.path.join(sdir, f))
           or os.readlink(os.path.join(sdir, f)) != "../d3plot.h5"]
    if bad:
        failures.append("%s: d3plot.states/ entries that are not links to ../d3plot.h5: %s"
                        % (tag, bad))
    if "d3plot.states" in open(xdmf).read():
        failures.append("%s: the final XDMF names state files" % tag)
    # 4. Reload Files: every state of the finished run
    ReloadFiles(reader)
    reader.UpdatePipelineInformation()
    final_times = times_of(reader)
    final = step(reader, final_times)
    if nst is None or len(final_times) != nst:
        failures.append("%s: after Reload Files ParaView sees %d states, d3plot.h5 has %s"
                        % (tag, len(final_times), nst))
    if final[:len(live)] != live:
        failures.append("%s: after Reload Files the first %d states differ from the live ones"
                        % (tag, len(live)))
    if any((p, c) != mesh for p, c, _ in final):
        failures.append("%s: a state after Reload Files lacks part of the mesh" % tag)
    print("%s: after Reload Files: %d states, von Mises max of the last %s"
          % (tag, len(final_times), final[-1][2] if final else None))
    return [v for _, _, v in final]


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    deck = os.path.abspath(sys.argv[1])
    outdir = os.path.abspath(sys.argv[2])
    nps = [int(a) for a in sys.argv[3:]] or [1]
    failures = []
    results = {}
    for np in nps:
        results[np] = live_run(deck, os.path.join(outdir, "live_np%d" % np), np, failures)
    ref = results[nps[0]]
    for np in nps[1:]:
        if results[np] != ref:
            failures.append("NP %d: the final von Mises ranges differ from NP %d's"
                            % (np, nps[0]))
    for f in failures:
        print("FAIL", f)
    print("live ParaView check:", "FAIL" if failures else "PASS")
    sys.stdout.flush()
    # no render-window teardown under Xvfb (it can raise a harmless GLXBadContext)
    os._exit(1 if failures else 0)


if __name__ == "__main__":
    sys.exit(main())
