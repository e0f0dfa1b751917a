"""A picture of a shell scene's plot state (decks/shell_projectile_plate, decks/shell_box_post).

Usage: xvfb-run -a -s "-screen 0 1280x1024x24" pvpython scripts/shell_scene_png.py \
           OUT/d3plot.xdmf TIME PNG [FIELD] [VIEW] [RANGE]
The state nearest TIME, coloured by the cell FIELD (default eff_plastic_strain) over RANGE
(lo,hi; default 0,0.1: fixed, so that the pictures of two runs compare), seen along VIEW (a
direction x,y,z; default 1,-1.4,0.8: from the side and above). Coordinates in the plot file
are the deformed ones."""
import sys

from paraview.simple import (Xdmf3ReaderS, GetActiveViewOrCreate, Show, ColorBy, Render,
                             SaveScreenshot, GetColorTransferFunction, ResetCamera)

xdmf, t, png = sys.argv[1], float(sys.argv[2]), sys.argv[3]
field = sys.argv[4] if len(sys.argv) > 4 else 'eff_plastic_strain'
view_dir = [float(c) for c in (sys.argv[5] if len(sys.argv) > 5 else '1,-1.4,0.8').split(',')]
r = Xdmf3ReaderS(FileName=[xdmf])
times = list(r.TimestepValues)
tn = min(times, key=lambda s: abs(s - t))
view = GetActiveViewOrCreate('RenderView')
view.ViewSize = [1000, 700]
view.ViewTime = tn
d = Show(r, view)
ColorBy(d, ('CELLS', field))
lut = GetColorTransferFunction(field)
lo, hi = (float(c) for c in (sys.argv[6] if len(sys.argv) > 6 else '0,0.1').split(','))
lut.RescaleTransferFunction(lo, hi)
d.SetScalarBarVisibility(view, True)
view.CameraPosition = view_dir
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
ResetCamera()
Render()
SaveScreenshot(png, view, ImageResolution=[1000, 700])
print(f'{png}: state t = {tn:g}, {field}')
