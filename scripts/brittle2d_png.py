"""The damage fringe PNG of decks/brittle_impact_2d (ParaView, not part of `make test`).

Usage: xvfb-run -a -s "-screen 0 1280x1024x24" pvpython scripts/brittle2d_png.py \
           OUT/d3plot.xdmf PNG [CX CY HALF]
Loads the XDMF (XDMF3 reader), goes to the last state, colours the cells by `damage`
(0..1, D = max(Dc, cracks opened / 3)), views the r-z plane around the impact (r 0..1.2 mm,
z -1..0.3 mm; or centred on CX, CY with the half height HALF, mm) and saves a 900 x 700 PNG.
"""
import os
import sys

from paraview.simple import (Xdmf3ReaderS, GetActiveViewOrCreate, Show, ColorBy, Render,
                             SaveScreenshot, GetAnimationScene, GetColorTransferFunction)


def main():
    xdmf, png = os.path.abspath(sys.argv[1]), sys.argv[2]
    cx, cy, half = (float(v) for v in sys.argv[3:6]) if len(sys.argv) > 5 else (0.6, -0.35, 0.7)
    r = Xdmf3ReaderS(FileName=[xdmf])
    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.AnimationTime = r.TimestepValues[-1]
    view = GetActiveViewOrCreate('RenderView')
    d = Show(r, view)
    ColorBy(d, ('CELLS', 'damage'))
    lut = GetColorTransferFunction('damage')
    lut.RescaleTransferFunction(0.0, 1.0)
    d.SetScalarBarVisibility(view, True)
    d.SetRepresentationType('Surface With Edges')
    view.ViewSize = [900, 700]
    Render(view)
    view.CameraPosition = [cx, cy, 5.0]
    view.CameraFocalPoint = [cx, cy, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraParallelProjection = 1
    view.CameraParallelScale = half
    view.OrientationAxesVisibility = 0
    Render(view)
    SaveScreenshot(png, view, ImageResolution=[900, 700])
    ok = os.path.isfile(png) and os.path.getsize(png) > 0
    print('PNG:', png, os.path.getsize(png) if ok else 0, 'bytes')
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
