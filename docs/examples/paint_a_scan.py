"""Paint a red stripe and a label onto the Stanford bunny, undo the label,
and write the result as VTK XML polydata (run with /usr/bin/python3 and
PYTHONPATH=build/python from the repository root)."""
import json
import os
import sys

import vtk
from vtkmodules.util.numpy_support import vtk_to_numpy

import meshpaint

here = os.path.dirname(os.path.abspath(__file__))
scan = os.path.join(here, "..", "..", "data", "scans", "bunny00.off")
out = sys.argv[1] if len(sys.argv) > 1 else "bunny_painted.vtp"

# Any VTK reader will do; OFF is read here through a tiny reader of our own
# would be needed, so take the points and faces from the file by hand.
with open(scan) as f:
    words = f.read().split()
nv, nf = int(words[1]), int(words[2])
points = vtk.vtkPoints()
for k in range(nv):
    points.InsertNextPoint(*(float(w) for w in words[4 + 3 * k: 7 + 3 * k]))
cells = vtk.vtkCellArray()
at = 4 + 3 * nv
for _ in range(nf):
    n = int(words[at])
    cells.InsertNextCell(n, [int(w) for w in words[at + 1: at + 1 + n]])
    at += n + 1
bunny = vtk.vtkPolyData()
bunny.SetPoints(points)
bunny.SetPolys(cells)

s = meshpaint.vtkPaintSurface()
s.SetInputData(bunny)
s.SetLevel(2)
s.ApplyStrokes(json.dumps({"strokes": [
    {"tool": "paint", "points": [[-0.3, 0.1, 0.3], [0.3, 0.1, 0.3]], "radius": 0.05,
     "channels": {"diffuse": [0.9, 0.1, 0.1]}},
    {"tool": "label", "points": [[0.0, 0.4, 0.0]], "radius": 0.1, "channels": {"label": 2}}]}))
s.Update()
s.Undo()  # the label goes again
s.Update()

surface = s.GetOutput()
diffuse = vtk_to_numpy(surface.GetPointData().GetArray("diffuse"))
print(f"{surface.GetNumberOfPoints()} points, {int((diffuse[:, 0] > 0.85).sum())} painted red, "
      f"{s.GetStrokeCount()} stroke(s) applied")

writer = vtk.vtkXMLPolyDataWriter()
writer.SetFileName(out)
writer.SetInputData(surface)
writer.Write()
