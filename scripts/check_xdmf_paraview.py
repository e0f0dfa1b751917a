"""Check that ParaView reads a dynx plot file (d3plot.xdmf + d3plot.h5).

Usage: xvfb-run -a -s "-screen 0 1280x1024x24" pvpython scripts/check_xdmf_paraview.py \
           OUT/d3plot.xdmf [NSTATES] [PNG]
(the 24-bit screen matters: with Xvfb's default screen ParaView may abort creating its window)

Loads the XDMF with the XDMF3 reader, checks the number of time steps (against NSTATES, or
against the nstates attribute of d3plot.h5 read with h5dump when NSTATES is not given), the
mesh size and the expected point/cell arrays at every time step, that every cell of the first
state has a positive volume (solids), area (shells) or length (beams) (connectivity order), then
colours the last state by von Mises stress and saves a PNG (default: next to the XDMF as
d3plot_check.png). When the last state has eroded elements (cell field failed = 1), a Threshold
on failed in [0, 0.5] (how a user hides them) must keep exactly the other cells.
Exit status 0 when all checks pass, 1 otherwise. Not part of `make test` (needs ParaView).
"""
import os
import re
import subprocess
import sys

from paraview import servermanager
from paraview.simple import (Xdmf3ReaderS, CellSize, GetActiveViewOrCreate, Show, ColorBy,
                             ResetCamera, Render, SaveScreenshot, Threshold)

POINT_ARRAYS = ["displacement", "velocity"]
CELL_ARRAYS = ["stress", "von_mises", "pressure", "eff_plastic_strain", "failed", "part_id"]


def nstates_from_h5(h5):
    out = subprocess.run(["h5dump", "-a", "/nstates", h5], capture_output=True, text=True)
    m = re.search(r"\(0\):\s*(\d+)", out.stdout)
    return int(m.group(1)) if m else None


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    xdmf = os.path.abspath(sys.argv[1])
    want = int(sys.argv[2]) if len(sys.argv) > 2 else nstates_from_h5(
        os.path.join(os.path.dirname(xdmf), "d3plot.h5"))
    png = sys.argv[3] if len(sys.argv) > 3 else os.path.join(os.path.dirname(xdmf),
                                                             "d3plot_check.png")
    failures = []
    reader = Xdmf3ReaderS(FileName=[xdmf])
    times = list(reader.TimestepValues) if reader.TimestepValues is not None else []
    if isinstance(reader.TimestepValues, float):
        times = [reader.TimestepValues]
    print("time steps:", len(times), times[:5], "..." if len(times) > 5 else "")
    if want is not None and len(times) != want:
        failures.append("expected %d time steps, ParaView sees %d" % (want, len(times)))
    reader.UpdatePipelineInformation()
    for t in times:
        reader.UpdatePipeline(t)      # the proxy method: time 0.0 is honoured
        info = reader.GetDataInformation()
        pd = reader.PointData.keys()
        cd = reader.CellData.keys()
        missing = [a for a in POINT_ARRAYS if a not in pd] + \
                  [a for a in CELL_ARRAYS if a not in cd]
        if missing:
            failures.append("t=%g: missing arrays %s" % (t, missing))
        if info.GetNumberOfCells() == 0 or info.GetNumberOfPoints() == 0:
            failures.append("t=%g: empty mesh" % t)
        vm = reader.CellData["von_mises"].GetRange() if "von_mises" in cd else None
        print("  t=%-12g points %d cells %d von_mises range %s" % (
            t, info.GetNumberOfPoints(), info.GetNumberOfCells(), vm))
    if times:
        sizes = CellSize(Input=reader)
        sizes.UpdatePipeline(times[0])
        vmin, vmax = sizes.CellData["Volume"].GetRange()
        print("cell volume range at first step:", (vmin, vmax))
        # shells (quadrilaterals, degenerate-quad triangles) have an area and no volume,
        # beams (polylines) a length: each cell must have one of them positive
        data = servermanager.Fetch(sizes)
        vol = data.GetCellData().GetArray("Volume")
        area = data.GetCellData().GetArray("Area")
        length = data.GetCellData().GetArray("Length")
        bad = [i for i in range(data.GetNumberOfCells())
               if not (vol.GetValue(i) > 0.0 or (area is not None and area.GetValue(i) > 0.0)
                       or (length is not None and length.GetValue(i) > 0.0))]
        if area is not None:
            print("cell area range at first step:", area.GetRange())
        if bad:
            failures.append("%d cells with no positive volume or area, first %d (node order?)"
                            % (len(bad), bad[0]))
    info = reader.GetDataInformation()
    print("points:", info.GetNumberOfPoints(), "cells:", info.GetNumberOfCells())
    print("point arrays:", reader.PointData.keys())
    print("cell arrays:", reader.CellData.keys())
    stress = reader.CellData["stress"] if "stress" in reader.CellData.keys() else None
    if stress is not None and stress.GetNumberOfComponents() != 6:
        failures.append("stress has %d components, expected 6" % stress.GetNumberOfComponents())
    if stress is not None:
        print("von_mises range at last step:", reader.CellData["von_mises"].GetRange())

    if times and "failed" in reader.CellData.keys():
        reader.UpdatePipeline(times[-1])
        data = servermanager.Fetch(reader)
        fl = data.GetCellData().GetArray("failed")
        nfail = sum(1 for i in range(data.GetNumberOfCells()) if fl.GetValue(i) > 0)
        if nfail:
            th = Threshold(Input=reader)
            th.Scalars = ["CELLS", "failed"]
            try:
                th.LowerThreshold, th.UpperThreshold = 0.0, 0.5
            except AttributeError:          # older ParaView: one range property
                th.ThresholdRange = [0.0, 0.5]
            th.UpdatePipeline(times[-1])
            kept = th.GetDataInformation().GetNumberOfCells()
            print("eroded cells at the last step: %d; Threshold failed <= 0.5 keeps %d of %d"
                  % (nfail, kept, data.GetNumberOfCells()))
            if kept != data.GetNumberOfCells() - nfail:
                failures.append("Threshold on failed keeps %d cells, expected %d"
                                % (kept, data.GetNumberOfCells() - nfail))

    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [640, 480]
    if times:
        view.ViewTime = times[-1]
    disp = Show(reader, view)
    ColorBy(disp, ("CELLS", "von_mises"))
    ResetCamera(view)
    Render(view)
    SaveScreenshot(png, view, ImageResolution=[640, 480])
    if not os.path.isfile(png) or os.path.getsize(png) == 0:
        failures.append("no PNG written to " + png)
    else:
        print("PNG:", png, os.path.getsize(png), "bytes")

    for f in failures:
        print("FAIL", f)
    print("ParaView check:", "FAIL" if failures else "PASS")
    sys.stdout.flush()
    # leave without tearing down the render window: under Xvfb that teardown can raise a
    # harmless GLXBadContext after all the work is done
    os._exit(1 if failures else 0)


if __name__ == "__main__":
    sys.exit(main())
