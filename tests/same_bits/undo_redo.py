#!/usr/bin/python3
"""Same-bits case for undo and redo through the Python package.

Usage: PYTHONPATH=BUILD/python LD_LIBRARY_PATH=BUILD/lib /usr/bin/python3 undo_redo.py OUTDIR

Paints femur.off at level 3 with vtkPaintSurface: strokes (paint, label,
sculpt, a coarse edit_level sculpt, smooth), undoes and redoes them, paints
again over an undone tail (dropping the redo), undoes and redoes that, then
continues from the saved project in a second filter. Writes into OUTDIR:

  step1.vtp ... step6.vtp   the output after each phase (vtkXMLPolyDataWriter defaults)
  history.json              GetHistoryJSON() of the first filter
  counts.txt                GetStrokeCount() after each phase
  project.meshpaint         SaveProject() of the first filter
  model/                    ExportModel() of the first filter
  loaded.vtp, loaded.meshpaint, loaded/   the same for the filter continued from project.meshpaint

Every file is compared byte for byte by scripts/same-bits.sh; the storage
comes from MESHPAINT_STORAGE.
"""
import json
import os
import sys

import vtk

import meshpaint

HERE = os.path.dirname(os.path.abspath(__file__))
SCANS = os.path.join(HERE, "..", "..", "data", "scans")

SHAFT = [[-0.10208, 0.10651, -0.14179], [-0.07283, 0.11072, -0.06817], [-0.0719, 0.1185, 0.01858],
         [-0.06876, 0.12549, 0.09492], [-0.04243, 0.13969, 0.18189], [-0.04393, 0.14918, 0.25342]]
CONDYLE = [[0.19934, -0.06107, -0.37522], [0.1905, -0.06235, -0.34269], [0.17794, -0.0575, -0.31737],
           [0.16738, -0.06192, -0.30039]]
LOWER = [[0.0812, -0.16887, -0.39099], [0.07578, -0.16401, -0.35132], [0.07828, -0.15866, -0.33848],
         [0.08541, -0.15403, -0.32707]]
UPPER = [[-0.0206, 0.16887, 0.43793], [-0.03673, 0.16587, 0.41603], [-0.02474, 0.16501, 0.39798],
         [-0.02931, 0.16302, 0.37708], [-0.0256, 0.16038, 0.35732]]


def read_off(path):
    """An OFF file as vtkPolyData (VTK 9.1 has no OFF reader)."""
    with open(path) as f:
        tokens = f.read().split()
    assert tokens[0] == "OFF"
    nv, nf = int(tokens[1]), int(tokens[2])
    points = vtk.vtkPoints()
    points.SetDataTypeToFloat()
    at = 4
    for _ in range(nv):
        points.InsertNextPoint(float(tokens[at]), float(tokens[at + 1]), float(tokens[at + 2]))
        at += 3
    polys = vtk.vtkCellArray()
    for _ in range(nf):
        n = int(tokens[at])
        polys.InsertNextCell(n)
        for k in range(n):
            polys.InsertCellPoint(int(tokens[at + 1 + k]))
        at += 1 + n
    poly = vtk.vtkPolyData()
    poly.SetPoints(points)
    poly.SetPolys(polys)
    return poly


def write_vtp(s, path):
    s.Update()
    out = vtk.vtkPolyData()
    out.DeepCopy(s.GetOutput())
    writer = vtk.vtkXMLPolyDataWriter()  # the defaults: appended binary data, zlib
    writer.SetInputData(out)
    writer.SetFileName(path)
    if writer.Write() != 1:
        raise SystemExit("cannot write " + path)


def path_points(coords):
    p = vtk.vtkPoints()
    for c in coords:
        p.InsertNextPoint(*c)
    return p


def main():
    if len(sys.argv) != 2:
        raise SystemExit("usage: undo_redo.py OUTDIR")
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    counts = []

    mesh = read_off(os.path.join(SCANS, "femur.off"))
    s = meshpaint.vtkPaintSurface()
    s.SetInputData(mesh)
    s.SetLevel(3)
    s.ApplyStrokes(json.dumps({"strokes": [
        {"points": SHAFT, "radius": 0.04, "falloff": "constant", "channels": {"diffuse": [0.9, 0.1, 0.1]}},
        {"tool": "label", "points": CONDYLE, "radius": 0.05, "channels": {"label": 3}},
        {"tool": "sculpt", "points": LOWER, "radius": 0.05, "amount": 0.004},
        {"tool": "sculpt", "points": UPPER, "radius": 0.08, "amount": 0.006, "edit_level": 1},
        {"tool": "smooth", "points": CONDYLE, "radius": 0.05, "iterations": 2},
    ]}))
    write_vtp(s, os.path.join(out, "step1.vtp"))  # all five strokes
    counts.append(s.GetStrokeCount())

    s.Undo()
    s.Undo()
    s.Undo()  # back to paint + label: the coarse edit's details go with it
    write_vtp(s, os.path.join(out, "step2.vtp"))
    counts.append(s.GetStrokeCount())

    s.Redo()
    s.Redo()  # sculpt and the coarse sculpt again; the smooth stays undone
    write_vtp(s, os.path.join(out, "step3.vtp"))
    counts.append(s.GetStrokeCount())

    # A new stroke over the undone tail drops the redo; set with the setters.
    s.SetTool("sculpt")
    s.SetRadius(0.06)
    s.SetAmount(-0.003)
    s.SetEditLevel(2)
    s.ApplyStroke(path_points(CONDYLE))
    s.SetTool("paint")
    s.SetEditLevel(0)
    s.SetRadius(0.03)
    s.SetFalloff("gaussian")
    s.SetOp("over")
    s.SetDiffuse(0.1, 0.2, 0.9)
    s.SetRoughness(0.2)
    s.ApplyStroke(path_points(UPPER))
    s.ClearChannels()
    s.SetTool("blur")
    s.SetIterations(3)
    s.SetRadius(0.04)
    s.ApplyStroke(path_points(SHAFT[:3]))
    write_vtp(s, os.path.join(out, "step4.vtp"))
    counts.append(s.GetStrokeCount())

    s.Undo()
    s.Undo()
    write_vtp(s, os.path.join(out, "step5.vtp"))
    counts.append(s.GetStrokeCount())
    s.Redo()
    write_vtp(s, os.path.join(out, "step6.vtp"))
    counts.append(s.GetStrokeCount())

    with open(os.path.join(out, "history.json"), "w") as f:
        f.write(s.GetHistoryJSON())
    s.SaveProject(os.path.join(out, "project.meshpaint"))
    s.ExportModel(os.path.join(out, "model"))

    # Continue from the project in a fresh filter, with one undo and redo.
    t = meshpaint.vtkPaintSurface()
    t.LoadProject(os.path.join(out, "project.meshpaint"))
    t.ApplyStrokes(json.dumps({"strokes": [
        {"tool": "inflate", "points": SHAFT[2:], "radius": 0.04, "amount": 0.002, "edit_level": 2},
        {"tool": "paint", "points": LOWER, "radius": 0.04, "channels": {"specular": [0.8, 0.8, 0.2]}},
    ]}))
    t.Update()
    t.Undo()
    t.Redo()
    write_vtp(t, os.path.join(out, "loaded.vtp"))
    counts.append(t.GetStrokeCount())
    t.SaveProject(os.path.join(out, "loaded.meshpaint"))
    t.ExportModel(os.path.join(out, "loaded"))

    with open(os.path.join(out, "counts.txt"), "w") as f:
        f.write(" ".join(str(c) for c in counts) + "\n")
    if counts != [5, 2, 4, 7, 5, 6, 2]:
        raise SystemExit("unexpected stroke counts %s" % counts)


if __name__ == "__main__":
    main()
