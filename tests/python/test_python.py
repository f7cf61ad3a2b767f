"""meshpaint from Python: the VTK classes, errors as exceptions, numpy, pipelines."""
import json
import os
import re
import subprocess
import sys

import numpy as np
import pytest
import vtk
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy

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
    # A screen-space spray seen from above: settings of other tools stay in
    # the brush but not in the stroke.
    s.SetTool("paint")
    s.SetDiffuse(1, 1, 0)
    s.SetSpace("screen")
    s.SetCamera(0, 0, 5, 0, 0, 0, 0, 1, 0, 30)
    s.SetBackfaces("skip")
    s.SetSpray(32, 0.02, 7)
    top = vtk.vtkPoints()
    top.InsertNextPoint(0, 0, 0.5)
    s.ApplyStroke(top)
    s.Update()
    assert s.GetStrokeCount() == 4
    brush = json.loads(s.GetBrushJSON())
    assert brush["space"] == "screen" and brush["spray"] == {"drops": 32, "size": 0.02, "seed": 7}
    history = json.loads(s.GetHistoryJSON())["strokes"]
    assert history[-1]["spray"]["drops"] == 32 and "amount" not in history[-1]


def painted_sphere():
    source = sphere()
    s = meshpaint.vtkPaintSurface()
    s.SetInputConnection(source.GetOutputPort())
    s.SetLevel(2)
    s.ApplyStrokes(json.dumps({"strokes": [
        {"points": [[0, 0, 0.5]], "radius": 0.2, "falloff": "constant", "channels": {"diffuse": [1, 0, 0]}},
        {"tool": "sculpt", "points": [[0, 0, 0.5]], "radius": 0.3, "amount": 0.05}]}))
    s.Update()
    return source, s


def arrays(poly):
    pd = poly.GetPointData()
    return {pd.GetArrayName(k): vtk_to_numpy(pd.GetArray(k)).copy() for k in range(pd.GetNumberOfArrays())}


def test_save_and_load_a_project(tmp_path):
    source, s = painted_sphere()
    before = s.GetOutput()
    s.SaveProject(tmp_path / "p.meshpaint")
    t = meshpaint.vtkPaintSurface()
    t.LoadProject(tmp_path / "p.meshpaint")
    assert t.GetLevel() == 2
    t.Update()
    after = t.GetOutput()
    assert np.array_equal(vtk_to_numpy(after.GetPoints().GetData()), vtk_to_numpy(before.GetPoints().GetData()))
    for name, values in arrays(before).items():
        assert np.array_equal(arrays(after)[name], values), name
    # continuing: one more stroke, saved again with the whole history
    t.ApplyStrokes('{"strokes": [{"tool": "label", "points": [[0, 0, -0.5]], "radius": 0.2, "channels": {"label": 2}}]}')
    t.SaveProject(tmp_path / "q.meshpaint")
    u = meshpaint.vtkPaintSurface()
    u.LoadProject(tmp_path / "q.meshpaint")
    history = json.loads(u.GetHistoryJSON())
    assert [st.get("tool", "paint") for st in history["strokes"]] == ["paint", "sculpt", "label"]
    assert history["level"] == 2
    with pytest.raises(meshpaint.Error, match="truncated project"):
        data = (tmp_path / "q.meshpaint").read_bytes()
        (tmp_path / "bad.meshpaint").write_bytes(data[:-5])
        meshpaint.vtkPaintSurface().LoadProject(tmp_path / "bad.meshpaint")


def test_export_model_writes_what_the_cli_writes(tmp_path):
    source, s = painted_sphere()
    s.ExportModel(tmp_path / "out")
    for name in ("surface.vtp", "model.obj", "model.mtl", "diffuse.png", "specular.png", "roughness.png",
                 "displacement.png"):
        assert (tmp_path / "out" / name).exists(), name
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(str(tmp_path / "out" / "surface.vtp"))
    reader.Update()
    assert np.array_equal(arrays(reader.GetOutput())["diffuse"], arrays(s.GetOutput())["diffuse"])


def test_channels_round_trip_through_numpy():
    from vtkmodules.util.numpy_support import numpy_to_vtk
    source, s = painted_sphere()
    diffuse = vtk_to_numpy(s.GetChannel("diffuse")).copy()
    assert np.array_equal(diffuse, arrays(s.GetOutput())["diffuse"])
    label = vtk_to_numpy(s.GetChannel("label"))
    assert label.dtype == np.int32 and not label.any()
    # paint every vertex below the equator green from numpy, and label it 7
    points = vtk_to_numpy(s.GetOutput().GetPoints().GetData())
    below = points[:, 2] < 0
    diffuse[below] = [0, 1, 0]
    s.SetChannel("diffuse", numpy_to_vtk(diffuse, deep=True))
    s.SetChannel("label", numpy_to_vtk(np.where(below, 7, 0).astype(np.int32), deep=True))
    s.Update()
    out = arrays(s.GetOutput())
    assert np.array_equal(out["diffuse"], diffuse.astype(np.float32))
    assert np.array_equal(out["label"] == 7, below)
    assert np.array_equal(vtk_to_numpy(s.GetChannel("diffuse")), out["diffuse"])
    with pytest.raises(meshpaint.Error, match="unknown channel 'colour'"):
        s.GetChannel("colour")
    with pytest.raises(meshpaint.Error, match="channel 'diffuse' has 3 components, the array 1"):
        s.SetChannel("diffuse", numpy_to_vtk(np.zeros(len(points), dtype=np.float32), deep=True))
    with pytest.raises(meshpaint.Error, match=r"channel 'roughness' needs \d+ values of 1 component, not 3 numbers"):
        s.SetChannel("roughness", numpy_to_vtk(np.zeros(3, dtype=np.float32), deep=True))
    # values a project could not hold are refused, and nothing is written
    bad = diffuse.copy()
    bad[5] = [0, np.nan, 0]
    with pytest.raises(meshpaint.Error, match=r"channel 'diffuse': the value of vertex \d+ is not finite"):
        s.SetChannel("diffuse", numpy_to_vtk(bad, deep=True))
    with pytest.raises(meshpaint.Error, match=r"channel 'displacement': the value of vertex \d+ is beyond 1e15"):
        s.SetChannel("displacement", numpy_to_vtk(np.full(len(points), 3e38, dtype=np.float32), deep=True))
    assert np.array_equal(vtk_to_numpy(s.GetChannel("diffuse")), out["diffuse"])


def test_nothing_to_paint_on():
    with pytest.raises(meshpaint.Error, match="nothing to paint on: set an input or load a project"):
        meshpaint.vtkPaintSurface().SaveProject("x.meshpaint")


def test_shared_arrays_follow_the_strokes_in_place():
    """With ShareArrays, the output's arrays are the engine's memory (PoCL):
    each update rewrites what changed in place, and the values are those of
    a source that copies, bit for bit."""
    source = sphere()
    shared, copied = meshpaint.vtkPaintSurface(), meshpaint.vtkPaintSurface()
    shared.ShareArraysOn()
    tri = vtk.vtkTriangleFilter()  # downstream filters see each change
    tri.SetInputConnection(shared.GetOutputPort())
    names = ("diffuse", "specular", "roughness", "displacement", "mask", "label", "Normals")
    steps = [{"points": [[0, 0, 0.5]], "radius": 0.25, "channels": {"diffuse": [1, 0, 0], "displacement": 0.01}},
             {"tool": "sculpt", "points": [[0.5, 0, 0]], "radius": 0.3, "amount": 0.05},
             "undo",
             {"tool": "label", "points": [[0, 0.5, 0]], "radius": 0.3, "channels": {"label": 3}}]
    for s in (shared, copied):
        s.SetInputConnection(source.GetOutputPort())
        s.SetLevel(3)
        s.Update()
    assert shared.GetSharingArrays() and not copied.GetSharingArrays()
    first = vtk_to_numpy(shared.GetOutput().GetPointData().GetArray("diffuse"))
    for step in steps:
        for s in (shared, copied):
            if step == "undo":
                s.Undo()
            else:
                s.ApplyStrokes(json.dumps({"strokes": [step]}))
            s.Update()
        a, b = shared.GetOutput(), copied.GetOutput()
        assert vtk_to_numpy(a.GetPoints().GetData()).tobytes() == vtk_to_numpy(b.GetPoints().GetData()).tobytes()
        for name in names:
            assert (vtk_to_numpy(a.GetPointData().GetArray(name)).tobytes() ==
                    vtk_to_numpy(b.GetPointData().GetArray(name)).tobytes()), (step, name)
        tri.Update()
        assert (vtk_to_numpy(tri.GetOutput().GetPoints().GetData()).tobytes() ==
                vtk_to_numpy(b.GetPoints().GetData()).tobytes())
    # the array read after the first update is the same memory, now painted
    assert (first[:, 1] == 0).any()
    assert first.tobytes() == vtk_to_numpy(copied.GetOutput().GetPointData().GetArray("diffuse")).tobytes()


def cube_soup(inward=False):
    """A unit cube as many exporters write it: every quad with its own four
    points (24 points, 6 quads), wound outward or, with `inward`, inward."""
    corners = [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    points, cells = vtk.vtkPoints(), vtk.vtkCellArray()
    for quad in quads:
        ids = [points.InsertNextPoint(*corners[c]) for c in quad]
        cells.InsertNextCell(4, list(reversed(ids)) if inward else ids)
    poly = vtk.vtkPolyData()
    poly.SetPoints(points)
    poly.SetPolys(cells)
    return poly


def test_polydata_input_goes_through_the_import_steps():
    # Welded and turned outward, as the same polygons read from a file are.
    s = meshpaint.vtkPaintSurface()
    s.SetInputData(cube_soup(inward=True))
    s.SetLevel(2)
    s.Update()
    report = s.GetImportReport()
    assert "welded 16 coincident vertices" in report, report
    assert "WeldOff() keeps them" in report and "--no-weld" not in report, report
    assert "turned 1 closed component wound inwards outward" in report, report
    out = s.GetOutput()
    welded_points = out.GetNumberOfPoints()
    # One closed surface: every limit normal points away from the centre.
    points = vtk_to_numpy(out.GetPoints().GetData())
    normals = vtk_to_numpy(out.GetPointData().GetArray("Normals"))
    assert (np.einsum("ij,ij->i", points - 0.5, normals) > 0).all()

    # WeldOff keeps the quads apart: six open sheets, more points, no weld reported.
    s.WeldOff()
    s.Update()
    assert "welded" not in s.GetImportReport(), s.GetImportReport()
    assert s.GetOutput().GetNumberOfPoints() > welded_points

    # The file's form and the polydata's give the same surface.
    poly_file = meshpaint.vtkPaintSurface()
    poly_file.SetInputData(cube_soup(inward=False))
    poly_file.SetLevel(2)
    poly_file.Update()
    assert poly_file.GetOutput().GetNumberOfPoints() == welded_points
    assert "outward" not in poly_file.GetImportReport()


def labelled_cube(classes=True):
    """The cube soup with a label array (top 5, the rest 2) and, with `classes`, the label classes
    as meshpaint's surface.vtp carries them: field data label_ids, label_names, label_colors."""
    poly = cube_soup()
    ids = vtk.vtkIntArray()
    ids.SetName("label")
    for i in range(poly.GetNumberOfPoints()):
        ids.InsertNextValue(5 if poly.GetPoint(i)[2] > 0.5 else 2)
    poly.GetPointData().AddArray(ids)
    if classes:
        class_ids, names, colours = vtk.vtkIntArray(), vtk.vtkStringArray(), vtk.vtkUnsignedCharArray()
        class_ids.SetName("label_ids")
        names.SetName("label_names")
        colours.SetName("label_colors")
        colours.SetNumberOfComponents(3)
        for i, name, rgb in ((2, "shaft", (255, 0, 0)), (5, "head", (0, 0, 255)), (9, "unused", (0, 255, 0))):
            class_ids.InsertNextValue(i)
            names.InsertNextValue(name)
            colours.InsertNextTuple3(*rgb)
        for a in (class_ids, names, colours):
            poly.GetFieldData().AddArray(a)
    return poly


def test_polydata_label_array_becomes_the_label_channel():
    # Welded points keep their ids, the top face's surface takes 5.
    s = meshpaint.vtkPaintSurface()
    s.SetInputData(labelled_cube(classes=False))
    s.SetLevel(2)
    s.Update()
    assert "took the polydata's 'label' array as the label channel (2 classes)" in s.GetImportReport()
    out = s.GetOutput()
    label = vtk_to_numpy(out.GetPointData().GetArray("label"))
    z = vtk_to_numpy(out.GetPoints().GetData())[:, 2]
    assert set(np.unique(label).tolist()) == {2, 5}
    assert (label[z > z.max() - 0.05] == 5).all() and (label[z < z.min() + 0.05] == 2).all()


def painted_cube_with_colours(colours, value, scalars):
    """A surface at level 2 on the cube soup whose every point has colour `value` in `colours`."""
    poly = cube_soup()
    colours.SetNumberOfComponents(3)
    for _ in range(poly.GetNumberOfPoints()):
        colours.InsertNextTuple3(*value)
    if scalars:
        poly.GetPointData().SetScalars(colours)
    else:
        poly.GetPointData().AddArray(colours)
    s = meshpaint.vtkPaintSurface()
    s.SetInputData(poly)
    s.SetLevel(2)
    s.Update()
    return s


def test_polydata_input_with_a_diffuse_array_starts_with_those_colours():
    colours = vtk.vtkFloatArray()
    colours.SetName("diffuse")
    s = painted_cube_with_colours(colours, (0.2, 0.4, 0.6), scalars=False)
    diffuse = vtk_to_numpy(s.GetChannel("diffuse"))
    assert np.allclose(diffuse, [0.2, 0.4, 0.6], atol=1e-6)
    assert "took the polydata's 'diffuse' array as the diffuse channel" in s.GetImportReport(), s.GetImportReport()


def test_polydata_byte_colours_are_reported_as_the_polydatas():
    rgb = vtk.vtkUnsignedCharArray()
    rgb.SetName("RGB")
    s = painted_cube_with_colours(rgb, (255, 0, 0), scalars=True)
    assert "took the polydata's colours as the diffuse channel" in s.GetImportReport(), s.GetImportReport()
    assert "file" not in s.GetImportReport()


def label_classes(s):
    colour = [0.0, 0.0, 0.0]
    out = []
    for i in range(s.GetNumberOfLabelClasses()):
        s.GetLabelClassColor(i, colour)
        out.append((s.GetLabelClassId(i), s.GetLabelClassName(i), tuple(round(c, 3) for c in colour)))
    return out


def test_polydata_label_field_data_gives_the_label_classes(tmp_path):
    s = meshpaint.vtkPaintSurface()
    s.SetInputData(labelled_cube())
    s.SetLevel(2)
    s.Update()
    expected = [(2, "shaft", (1.0, 0.0, 0.0)), (5, "head", (0.0, 0.0, 1.0)), (9, "unused", (0.0, 1.0, 0.0))]
    assert label_classes(s) == expected
    assert "took the names and colours of 3 label classes from the polydata" in s.GetImportReport()
    # ExportModel and SaveProject carry them; the exported surface read back gives them again.
    s.ExportModel(tmp_path / "out")
    r = vtk.vtkXMLPolyDataReader()
    r.SetFileName(str(tmp_path / "out" / "surface.vtp"))
    r.Update()
    names = r.GetOutput().GetFieldData().GetAbstractArray("label_names")
    assert [names.GetValue(i) for i in range(names.GetNumberOfValues())] == ["shaft", "head", "unused"]
    again = meshpaint.vtkPaintSurface()
    again.SetInputData(r.GetOutput())
    again.SetLevel(1)
    again.Update()
    assert label_classes(again) == expected
    s.SaveProject(tmp_path / "p.meshpaint")
    loaded = meshpaint.vtkPaintSurface()
    loaded.LoadProject(tmp_path / "p.meshpaint")
    assert label_classes(loaded) == expected
    # Without field data: a class "label ID" for each id.
    plain = meshpaint.vtkPaintSurface()
    plain.SetInputData(labelled_cube(classes=False))
    plain.SetLevel(1)
    plain.Update()
    assert [(i, name) for i, name, _ in label_classes(plain)] == [(2, "label 2"), (5, "label 5")]


def test_polydata_label_field_data_that_disagrees_raises():
    poly = labelled_cube()
    poly.GetFieldData().GetAbstractArray("label_names").SetValue(1, "shaft")  # two classes of one name
    s = meshpaint.vtkPaintSurface()
    s.SetInputData(poly)
    with pytest.raises(meshpaint.Error, match="label classes of the field data"):
        s.Update()


def test_polydata_float_arrays_become_channels():
    poly = cube_soup()
    z = vtk_to_numpy(poly.GetPoints().GetData())[:, 2]
    for name, values in (("roughness", 0.2 + 0.6 * z), ("Curvature", 1 - z)):
        a = numpy_to_vtk(values.astype("float32"), deep=True)
        a.SetName(name)
        poly.GetPointData().AddArray(a)
    s = meshpaint.vtkPaintSurface()
    s.SetInputData(poly)
    s.SetLevel(2)
    s.AddImportArray("Curvature", "mask")
    s.Update()
    report = s.GetImportReport()
    assert "took the polydata's 'roughness' array as the roughness channel (24 vertices)" in report, report
    assert "took the polydata's 'Curvature' array as the mask channel (24 vertices)" in report, report
    out_z = vtk_to_numpy(s.GetOutput().GetPoints().GetData())[:, 2]
    assert np.corrcoef(out_z, vtk_to_numpy(s.GetChannel("roughness")))[0, 1] > 0.95
    assert np.corrcoef(out_z, vtk_to_numpy(s.GetChannel("mask")))[0, 1] < -0.95
    with pytest.raises(meshpaint.Error, match="unknown channel 'shine'"):
        s.AddImportArray("Curvature", "shine")
    s.RemoveAllImportArrays()
    s.AddImportArray("Missing", "mask")
    with pytest.raises(meshpaint.Error, match="has no vertex array 'Missing'"):
        s.Update()


def test_bad_polydata_input_raises():
    poly = cube_soup()
    poly.GetPoints().SetPoint(3, float("nan"), 0, 0)
    s = meshpaint.vtkPaintSurface()
    s.SetInputData(poly)
    with pytest.raises(meshpaint.Error, match="input polygons: vertex 3 has a non-finite coordinate"):
        s.Update()


@pytest.mark.parametrize("offsets, message", [
    ([4, 8, 12, 16, 20, 24, 28], "the first polygon offset is 4, not 0"),
    ([0, 4, 8, 6, 16, 20, 24], "polygon 2 has -2 points: the cell offsets decrease"),
    ([0, 4, 8, 12, 16, 20, 10 ** 9], "polygon 5 ends at offset 1000000000, past the 24 point ids"),
])
def test_polydata_with_bad_cell_offsets_raises(offsets, message):
    # Offsets a traversal would trust: checked whole before any polygon is read.
    poly = cube_soup()
    conn = numpy_to_vtk(np.arange(24, dtype=np.int64), deep=True, array_type=vtk.VTK_TYPE_INT64)
    offs = numpy_to_vtk(np.array(offsets, dtype=np.int64), deep=True, array_type=vtk.VTK_TYPE_INT64)
    cells = vtk.vtkCellArray()
    cells.SetData(offs, conn)
    poly.SetPolys(cells)
    s = meshpaint.vtkPaintSurface()
    s.SetInputData(poly)
    with pytest.raises(meshpaint.Error, match=message):
        s.Update()


def test_saves_take_the_project_lock(tmp_path):
    source, s = painted_sphere()
    path = tmp_path / "p.meshpaint"
    s.SaveProject(path)
    marker = tmp_path / "released"
    # Another process in the middle of continuing the project: it holds the
    # lock, then notes that it lets go.
    holder = subprocess.Popen([sys.executable, "-c", (
        "import fcntl, sys, time\n"
        "f = open(sys.argv[1], 'rb')\n"
        "fcntl.flock(f, fcntl.LOCK_EX)\n"
        "print('locked', flush=True)\n"
        "time.sleep(1)\n"
        "open(sys.argv[2], 'w').close()\n"), str(path), str(marker)], stdout=subprocess.PIPE, text=True)
    assert holder.stdout.readline().strip() == "locked"
    s.SaveProject(path)  # waits for its turn
    assert marker.exists()
    holder.wait(timeout=60)


def test_a_save_over_a_project_another_run_saved_meanwhile_is_refused(tmp_path):
    source, s = painted_sphere()
    path = tmp_path / "p.meshpaint"
    s.SaveProject(path)
    t = meshpaint.vtkPaintSurface()
    t.LoadProject(path)
    t.ApplyStrokes('{"strokes": [{"tool": "label", "points": [[0, 0, -0.5]], "radius": 0.2, "channels": {"label": 2}}]}')
    t.SaveProject(path)  # its own earlier save is no obstacle
    t.SaveProject(path)
    # Another run continues the project meanwhile: its stroke is in the file now.
    script = tmp_path / "more.json"
    script.write_text('{"strokes": [{"points": [[0, 0, 0.5]], "radius": 0.2, "channels": {"diffuse": [0, 1, 0]}}]}')
    bin_dir = os.path.join(os.path.dirname(meshpaint.__file__), "..", "..", "bin", "meshpaint")
    r = subprocess.run([bin_dir, "paint", str(path), "--strokes", str(script), "--save", str(path), "--quiet"],
                       capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    before = path.read_bytes()
    with pytest.raises(meshpaint.Error, match="was saved by another run"):
        t.SaveProject(path)
    assert path.read_bytes() == before
    t.SaveProject(tmp_path / "elsewhere.meshpaint")  # saving under another name is fine


@pytest.mark.parametrize("name,components", [("Colors", 3), ("RGBA", 4), (None, 3)])
def test_rgb_bytes_as_other_tools_write_them_become_the_diffuse_channel(tmp_path, name, components):
    # ParaView, MeshLab and Blender's VTK export: unsigned bytes per point,
    # named Colors/RGB/RGBA or set as the point scalars.
    poly = cube_soup()
    colours = vtk.vtkUnsignedCharArray()
    colours.SetName(name or "anything")
    colours.SetNumberOfComponents(components)
    for _ in range(poly.GetNumberOfPoints()):
        colours.InsertNextTuple([51, 102, 204, 255][:components])
    if name is None:
        poly.GetPointData().SetScalars(colours)
    else:
        poly.GetPointData().AddArray(colours)
    s = meshpaint.vtkPaintSurface()
    s.SetInputData(poly)
    s.SetLevel(2)
    s.Update()
    assert np.allclose(vtk_to_numpy(s.GetChannel("diffuse")), [0.2, 0.4, 0.8], atol=1e-6)
    # The same written by VTK's XML writer, read by the command line.
    writer = vtk.vtkXMLPolyDataWriter()
    writer.SetInputData(poly)
    writer.SetFileName(str(tmp_path / "coloured.vtp"))
    writer.Write()
    binary = os.path.join(os.path.dirname(meshpaint.__file__), "..", "..", "bin", "meshpaint")
    r = subprocess.run([binary, "info", str(tmp_path / "coloured.vtp")], capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    assert "took the file's colours as the diffuse channel" in r.stdout + r.stderr


def test_a_stroke_that_fails_while_painting_leaves_no_step():
    # A coarse sculpt under a memory cap that holds the painting at level 4
    # but not the multiresolution layers: the error is raised, and the
    # history (what a saved project replays) has no step for it.
    cube = os.path.join(SOURCE, "tests", "support", "cube.obj")
    bin_path = os.path.join(os.path.dirname(meshpaint.__file__), "..", "..", "bin", "meshpaint")
    r = subprocess.run([bin_path, "info", cube], capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    row = next(l for l in r.stdout.splitlines() if re.match(r"\s*4\s", l))
    units = {"B": 1, "KiB": 1 << 10, "MiB": 1 << 20, "GiB": 1 << 30}
    sizes = [float(v) * units[u] for v, u in re.findall(r"([0-9.]+) (B|KiB|MiB|GiB)", row)]
    painting, coarse = sizes[-2], sizes[-1]
    child = (
        "import json, sys, vtk, meshpaint\n"
        "reader = vtk.vtkOBJReader(); reader.SetFileName(sys.argv[1]); reader.Update()\n"
        "s = meshpaint.vtkPaintSurface(); s.SetInputData(reader.GetOutput()); s.SetLevel(4); s.Update()\n"
        "s.ApplyStrokes(json.dumps({'strokes': [{'tool': 'sculpt', 'points': [[0.5, 0.5, 1]], 'radius': 0.3,\n"
        "                                        'amount': 0.05, 'edit_level': 1}]}))\n"
        "try:\n"
        "    s.Update()\n"
        "    print('painted')\n"
        "except meshpaint.Error as e:\n"
        "    print('error:', e)\n"
        "print(len(json.loads(s.GetHistoryJSON())['strokes']))\n")
    env = dict(os.environ, MESHPAINT_DEVICE_MEMORY=str(int((painting + coarse) / 2)))
    r = subprocess.run([sys.executable, "-c", child, cube], capture_output=True, text=True, timeout=600, env=env)
    assert r.returncode == 0, r.stderr
    message, strokes = r.stdout.strip().splitlines()[-2:]
    assert message.startswith("error: editing below painting level 4 needs"), r.stdout
    assert strokes == "0", r.stdout
