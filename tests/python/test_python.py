"""meshpaint from Python: the VTK classes, errors as exceptions, numpy, pipelines."""
import json
import os
import subprocess
import sys

import numpy as np
import pytest
import vtk
from vtkmodules.util.numpy_support import vtk_to_numpy

import meshpaint

SOURCE = os.environ["MESHPAINT_SOURCE_DIR"]


def sphere():
    src = vtk.vtkSphereSource()
    src.SetThetaResolution(24)
    src.SetPhiResolution(12)
    src.Update()
    return src


def test_the_guide_example():
    s = meshpaint.vtkPaintSurface()
    assert isinstance(s, vtk.vtkPolyDataAlgorithm)
    s.SetInputData(sphere().GetOutput())
    s.SetLevel(3)
    s.ApplyStrokes(json.dumps({"strokes": [
        {"points": [[0, 0, 0.5]], "radius": 0.2, "falloff": "constant", "channels": {"diffuse": [1, 0, 0]}}]}))
    s.Update()
    out = s.GetOutput()
    for name in ("diffuse", "specular", "roughness", "displacement", "label", "Normals"):
        assert out.GetPointData().GetArray(name) is not None, name
    diffuse = vtk_to_numpy(out.GetPointData().GetArray("diffuse"))
    points = vtk_to_numpy(out.GetPoints().GetData())
    red = diffuse[:, 1] == 0
    assert red.any()
    # The brush centre snaps to the surface point closest to (0, 0, 0.5).
    centre = points[np.argmin(np.linalg.norm(points - [0, 0, 0.5], axis=1))]
    assert np.all(np.linalg.norm(points[red] - centre, axis=1) <= 0.2 + 1e-5)
    s.Undo()
    s.Update()
    assert not (vtk_to_numpy(s.GetOutput().GetPointData().GetArray("diffuse"))[:, 1] == 0).any()
    s.Redo()
    s.Update()
    assert (vtk_to_numpy(s.GetOutput().GetPointData().GetArray("diffuse"))[:, 1] == 0).sum() == red.sum()


def test_errors_are_exceptions_with_the_cli_message():
    s = meshpaint.vtkPaintSurface()
    with pytest.raises(meshpaint.Error, match=r'stroke 0: "radius" must be a number'):
        s.ApplyStrokes('{"strokes": [{"points": [[0,0,0]], "radius": -1, "channels": {"diffuse": [1,0,0]}}]}')
    with pytest.raises(meshpaint.Error, match="nothing painted yet"):
        s.Undo()
    s.SetInputData(vtk.vtkPolyData())
    with pytest.raises(meshpaint.Error, match="has no faces"):
        s.Update()


def test_in_a_vtk_pipeline(tmp_path):
    source = sphere()  # a pipeline needs its producers kept alive
    s = meshpaint.vtkPaintSurface()
    s.SetInputConnection(source.GetOutputPort())
    s.SetLevel(2)
    s.ApplyStrokes('{"strokes": [{"tool": "sculpt", "points": [[0,0,0.5]], "radius": 0.3, "amount": 0.05}]}')
    tri = vtk.vtkTriangleFilter()
    tri.SetInputConnection(s.GetOutputPort())
    writer = vtk.vtkXMLPolyDataWriter()
    writer.SetInputConnection(tri.GetOutputPort())
    writer.SetFileName(str(tmp_path / "out.vtp"))
    writer.Write()
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(str(tmp_path / "out.vtp"))
    reader.Update()
    points = vtk_to_numpy(reader.GetOutput().GetPoints().GetData())
    assert points[:, 2].max() > 0.5 + 0.02  # the sculpted bump


def test_catmull_clark_filter():
    source = sphere()
    f = meshpaint.vtkCatmullClarkAtlasFilter()
    f.SetInputConnection(source.GetOutputPort())
    f.SetLevel(2)
    f.Update()
    assert f.GetOutput().GetNumberOfPolys() > 0


def test_guide_example_script_runs(tmp_path):
    env = dict(os.environ)
    r = subprocess.run([sys.executable, os.path.join(SOURCE, "docs", "examples", "paint_a_scan.py"),
                        str(tmp_path / "bunny.vtp")], capture_output=True, text=True, env=env, timeout=600)
    assert r.returncode == 0, r.stderr
    assert "painted red" in r.stdout
    assert (tmp_path / "bunny.vtp").exists()


def test_a_failed_call_does_not_poison_the_next_update():
    s = meshpaint.vtkPaintSurface()
    s.SetInputData(sphere().GetOutput())
    s.SetLevel(2)
    s.Update()
    with pytest.raises(meshpaint.Error, match="nothing to undo"):
        s.Undo()
    s.Update()  # fine: the failed Undo was not an update failure
    assert s.GetOutput().GetNumberOfPoints() > 0


def test_brush_setters_and_a_vtkpoints_path():
    s = meshpaint.vtkPaintSurface()
    s.SetInputData(sphere().GetOutput())
    s.SetLevel(2)
    s.SetRadius(0.15)
    s.SetFalloff("constant")
    s.SetDiffuse(0, 0, 1)
    s.SetRoughness(0.9)
    path = vtk.vtkPoints()
    path.InsertNextPoint(0, 0, 0.5)
    path.InsertNextPoint(0.3, 0, 0.4)
    s.ApplyStroke(path)
    s.Update()
    out = s.GetOutput()
    diffuse = vtk_to_numpy(out.GetPointData().GetArray("diffuse"))
    rough = vtk_to_numpy(out.GetPointData().GetArray("roughness"))
    blue = (diffuse[:, 2] == 1) & (diffuse[:, 0] == 0)
    assert blue.sum() > 10
    assert np.all(rough[blue] == np.float32(0.9))
    assert json.loads(s.GetBrushJSON())["channels"]["diffuse"] == [0, 0, 1]
    s.SetRadius(-1)
    with pytest.raises(meshpaint.Error, match=r'stroke 0: "radius" must be a number'):
        s.ApplyStroke(path)
    s.SetRadius(0.2)
    s.ClearChannels()
    s.SetTool("sculpt")
    s.SetAmount(0.05)
    s.ApplyStroke(path)
    s.Update()
    assert s.GetStrokeCount() == 2
    # A grab at a coarser edit level: the finest level follows.
    s.SetTool("grab")
    s.SetEditLevel(1)
    assert json.loads(s.GetBrushJSON())["edit_level"] == 1
    pull = vtk.vtkPoints()
    pull.InsertNextPoint(0.3, 0, 0.4)
    pull.InsertNextPoint(0.3, 0, 0.6)
    s.ApplyStroke(pull)
    s.Update()
    assert s.GetStrokeCount() == 3
    s.SetEditLevel(0)
    assert "edit_level" not in json.loads(s.GetBrushJSON())
