"""Point data of other tools (and meshpaint's own outputs) arriving in the channels.

Files are written as VTK's writers and MeshLab write them: vtkXMLPolyDataWriter,
vtkPolyDataWriter, vtkPLYWriter, and a hand-written PLY with `property float quality`.
"""
import json
import locale
import os
import struct
import subprocess

import numpy as np
import pytest
import vtk
from vtkmodules.util import numpy_support

BIN = os.environ["MESHPAINT_BIN"]
CHANNELS = {"diffuse": 3, "specular": 3, "roughness": 1, "displacement": 1, "mask": 1}


def run(*args):
    return subprocess.run([BIN, *map(str, args)], capture_output=True, text=True, timeout=600)


def read_vtp(path):
    r = vtk.vtkXMLPolyDataReader()
    r.SetFileName(str(path))
    r.Update()
    return r.GetOutput()


def array(poly, name):
    return numpy_support.vtk_to_numpy(poly.GetPointData().GetArray(name))


def sphere():
    s = vtk.vtkSphereSource()
    s.SetThetaResolution(12)
    s.SetPhiResolution(8)
    s.SetRadius(0.5)
    s.Update()
    return s.GetOutput()


def write_vtp(poly, path):
    w = vtk.vtkXMLPolyDataWriter()
    w.SetInputData(poly)
    w.SetFileName(str(path))
    assert w.Write() == 1
    return str(path)


def paint(mesh, out, strokes, *flags, level=2):
    r = run("paint", mesh, "--strokes", strokes, "--level", level, "-o", out, "--quiet", *flags)
    assert r.returncode == 0, r.stderr
    return read_vtp(os.path.join(out, "surface.vtp"))


@pytest.fixture(scope="module")
def painted(tmp_path_factory):
    """A sphere painted in every channel, with two named label classes, as `paint -o` writes it."""
    d = tmp_path_factory.mktemp("painted")
    mesh = write_vtp(sphere(), d / "sphere.vtp")
    (d / "s.json").write_text(json.dumps({"strokes": [
        {"tool": "wash", "channels": {"diffuse": [0.2, 0.5, 0.7], "specular": [0.1, 0.2, 0.3], "roughness": 0.3,
                                      "mask": 0.25}},
        {"tool": "paint", "points": [[0, 0, 0.5]], "radius": 0.3,
         "channels": {"diffuse": [0.9, 0.1, 0.1], "specular": [0.5, 0.5, 0.5], "roughness": 0.9,
                      "displacement": 0.02, "mask": 0.75}},
        {"tool": "label", "points": [[0.5, 0, 0]], "radius": 0.3, "channels": {"label": 3}},
        {"tool": "label", "points": [[-0.5, 0, 0]], "radius": 0.3, "channels": {"label": 5}}]}))
    (d / "labels.json").write_text(json.dumps([
        {"id": 3, "name": "cortex", "colour": [1, 0, 0]}, {"id": 5, "name": "marrow", "colour": [0, 0, 1]}]))
    (d / "none.json").write_text('{"strokes": []}')
    poly = paint(mesh, d / "out", d / "s.json", "--labels", d / "labels.json", level=2)
    return d, poly


def incident_ranges(poly, values):
    """Per point: the smallest and largest value over the points of its cells (its one-ring of faces)."""
    k = values.reshape(len(values), -1)
    low, high = k.copy(), k.copy()
    ids = vtk.vtkIdList()
    for c in range(poly.GetNumberOfCells()):
        poly.GetCellPoints(c, ids)
        corners = [ids.GetId(i) for i in range(ids.GetNumberOfIds())]
        lo, hi = k[corners].min(axis=0), k[corners].max(axis=0)
        for p in corners:
            low[p] = np.minimum(low[p], lo)
            high[p] = np.maximum(high[p], hi)
    return low, high


def nearest(points, to):
    return np.array([int(np.argmin(((points - p) ** 2).sum(axis=1))) for p in to])


def check_values_come_back(given_poly, mesh, out, strokes, channels):
    """`mesh` painted again at level 1 holds the channel values of `given_poly` (the same points) at its
    base vertices: exactly where the file's values are even around a vertex, else within its neighbours'."""
    back = paint(mesh, out, strokes, level=1)
    n = given_poly.GetNumberOfPoints()
    base = numpy_support.vtk_to_numpy(given_poly.GetPoints().GetData())
    at = nearest(numpy_support.vtk_to_numpy(back.GetPoints().GetData()), base)
    for channel in channels:
        k = CHANNELS[channel]
        given, got = array(given_poly, channel).reshape(n, k), array(back, channel)[at].reshape(n, k)
        low, high = incident_ranges(given_poly, given)
        even = (low == high).all(axis=1)
        assert (given.max(axis=0) > given.min(axis=0)).all(), channel  # the painting varies ...
        assert even.sum() > n // 4 and (~even).any(), channel       # ... in places
        assert np.abs(got[even] - given[even]).max() < 1e-6, channel
        # Catmull-Clark's weights are positive: a value never leaves its neighbours' range.
        assert (got >= low - 1e-6).all() and (got <= high + 1e-6).all(), channel


def test_paint_reads_its_own_vtp_output_with_every_channel(painted):
    d, first = painted
    r = run("info", d / "out" / "surface.vtp")
    assert r.returncode == 0, r.stderr
    n = first.GetNumberOfPoints()
    for channel in CHANNELS:
        assert f"took the file's '{channel}' array as the {channel} channel ({n} vertices)" in r.stdout, r.stdout
    check_values_come_back(first, d / "out" / "surface.vtp", d / "again", d / "none.json", CHANNELS)


def test_the_label_classes_of_meshpaints_vtp_come_back_by_name(painted):
    d, first = painted
    r = run("stats", d / "out" / "surface.vtp", "--json")
    assert r.returncode == 0, r.stderr
    rows = {row["id"]: row for row in json.loads(r.stdout)["labels"]}
    assert rows[3]["name"] == "cortex" and rows[5]["name"] == "marrow", rows
    assert "took the names and colours of 2 label classes from the file" in r.stderr
    again = paint(d / "out" / "surface.vtp", d / "classes", d / "none.json", level=1)
    fd = again.GetFieldData()
    names = fd.GetAbstractArray("label_names")
    assert [names.GetValue(i) for i in range(names.GetNumberOfValues())] == ["cortex", "marrow"]
    assert numpy_support.vtk_to_numpy(fd.GetArray("label_colors")).tolist() == [[255, 0, 0], [0, 0, 255]]


def test_transferred_ply_comes_back_with_its_float_channels(painted, tmp_path):
    d, first = painted
    project = tmp_path / "p.meshpaint"
    r = run("paint", d / "sphere.vtp", "--strokes", d / "s.json", "--level", 2, "--save", project, "--quiet")
    assert r.returncode == 0, r.stderr
    for ext in ("ply", "vtp"):
        r = run("transfer", project, "--to", d / "sphere.vtp", "-o", tmp_path / f"scan.{ext}", "--quiet")
        assert r.returncode == 0, r.stderr
    r = run("info", tmp_path / "scan.ply")
    assert r.returncode == 0, r.stderr
    n = sphere().GetNumberOfPoints()
    channels = [c for c in CHANNELS if c != "mask"]  # transfer writes no mask
    for channel in channels:
        assert f"took the file's '{channel}' array as the {channel} channel ({n} vertices)" in r.stdout, r.stdout
    # The float diffuse (diffuse_r, _g, _b) wins over the byte colours red, green, blue.
    assert "took the file's colours" not in r.stdout
    check_values_come_back(read_vtp(tmp_path / "scan.vtp"), tmp_path / "scan.ply", tmp_path / "again",
                           d / "none.json", channels)


def meshlab_ply(quality, binary=False):
    """A grid as MeshLab writes a mesh with per-vertex quality."""
    points = [(x, y, 0.0) for y in range(3) for x in range(3)]
    faces = [(y * 3 + x, y * 3 + x + 1, y * 3 + x + 4, y * 3 + x + 3) for y in range(2) for x in range(2)]
    head = ("ply\nformat " + ("binary_little_endian" if binary else "ascii") + " 1.0\ncomment VCGLIB generated\n"
            f"element vertex {len(points)}\nproperty float x\nproperty float y\nproperty float z\n"
            "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\n"
            "property float quality\n"
            f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n").encode()
    if binary:
        body = b"".join(struct.pack("<3f4Bf", *p, 128, 128, 128, 255, q) for p, q in zip(points, quality))
        body += b"".join(struct.pack("<B4i", 4, *f) for f in faces)
    else:
        body = "".join(f"{p[0]} {p[1]} {p[2]} 128 128 128 255 {q}\n" for p, q in zip(points, quality)).encode()
        body += "".join("4 " + " ".join(map(str, f)) + "\n" for f in faces).encode()
    return head + body


QUALITY = [0.0, 0.0, 0.0, 0.5, 0.5, 0.5, 1.0, 1.0, 1.0]  # rising with y


@pytest.mark.parametrize("binary", [False, True])
def test_meshlab_quality_goes_into_the_channel_it_is_mapped_to(tmp_path, binary):
    mesh = tmp_path / "grid.ply"
    mesh.write_bytes(meshlab_ply(QUALITY, binary))
    (tmp_path / "none.json").write_text('{"strokes": []}')
    r = run("info", mesh, "--import-array", "quality:roughness")
    assert r.returncode == 0, r.stderr
    assert "took the file's 'quality' array as the roughness channel (9 vertices)" in r.stdout
    assert "took the file's 'quality' array as the roughness channel (9 vertices)" in r.stderr
    out = paint(mesh, tmp_path / "out", tmp_path / "none.json", "--import-array", "quality:roughness",
                "--import-array", "quality:mask")
    y = numpy_support.vtk_to_numpy(out.GetPoints().GetData())[:, 1]
    for channel in ("roughness", "mask"):
        v = array(out, channel)
        assert v.min() >= 0 and v.max() <= 1
        assert np.corrcoef(y, v)[0, 1] > 0.95, channel  # follows the file's field
    # Without the mapping, nothing becomes a channel: quality is no channel name.
    r = run("info", mesh)
    assert "'quality'" not in r.stdout + r.stderr


@pytest.mark.parametrize("quality, message", [
    ([0.5] * 8 + [1.5], "array 'quality' (for the roughness channel): vertex 8 is not from 0 to 1 (1.5)"),
    ([0.5] * 8 + [float("nan")], "array 'quality' (for the roughness channel): vertex 8 is not finite (nan)"),
    ([0.5] * 8 + [float("inf")], "array 'quality' (for the roughness channel): vertex 8 is not finite (inf)"),
])
def test_out_of_range_values_give_one_line_naming_the_array(tmp_path, quality, message):
    mesh = tmp_path / "grid.ply"
    mesh.write_bytes(meshlab_ply(quality, binary=True))
    r = run("info", mesh, "--import-array", "quality:roughness")
    assert r.returncode == 2 and r.stderr.count("\n") == 1 and message in r.stderr, r.stderr


def test_non_finite_text_property_names_the_property(tmp_path):
    mesh = tmp_path / "grid.ply"
    mesh.write_bytes(meshlab_ply([0.5] * 8 + [float("nan")]))
    r = run("info", mesh, "--import-array", "quality:roughness")
    assert r.returncode == 2 and r.stderr.count("\n") == 1, r.stderr
    assert "vertex 8 has the non-finite value 'nan' in its property 'quality'" in r.stderr, r.stderr


@pytest.mark.parametrize("flag, message", [
    ("curvature:roughness", "has no vertex array 'curvature' for --import-array (it has quality)"),
    ("quality:specular", "array 'quality' has 1 component; the specular channel takes 3"),
    ("quality:shine", "unknown channel 'shine' (diffuse, specular, roughness, displacement, label, mask)"),
    ("quality", "--import-array needs NAME:CHANNEL, not 'quality'"),
])
def test_bad_import_array_gives_one_line_and_exit_2(tmp_path, flag, message):
    mesh = tmp_path / "grid.ply"
    mesh.write_bytes(meshlab_ply(QUALITY))
    (tmp_path / "none.json").write_text('{"strokes": []}')
    for command in ("info", "stats", "paint"):
        extra = ["--strokes", tmp_path / "none.json", "-o", tmp_path / "o"] if command == "paint" else []
        r = run(command, mesh, "--import-array", flag, *extra)
        assert r.returncode == 2 and r.stderr.count("\n") == 1 and message in r.stderr, (command, r.stderr)


def test_a_channel_mapped_twice_is_refused(tmp_path):
    mesh = tmp_path / "grid.ply"
    mesh.write_bytes(meshlab_ply(QUALITY))
    r = run("info", mesh, "--import-array", "quality:roughness", "--import-array", "quality:roughness")
    assert r.returncode == 2 and "--import-array names the roughness channel twice" in r.stderr, r.stderr


def test_import_array_is_refused_for_a_project(painted, tmp_path):
    d, _ = painted
    project = tmp_path / "p.meshpaint"
    assert run("paint", d / "sphere.vtp", "--strokes", d / "none.json", "--save", project).returncode == 0
    r = run("info", project, "--import-array", "quality:roughness")
    assert r.returncode == 2 and "--import-array reads mesh files" in r.stderr, r.stderr


def curvature_sphere():
    """A sphere with a VTK scalar array Curvature (z mapped to 0..1) and a float roughness array."""
    poly = sphere()
    z = numpy_support.vtk_to_numpy(poly.GetPoints().GetData())[:, 2]
    for name, values in (("Curvature", z + 0.5), ("roughness", 0.5 - z)):
        a = numpy_support.numpy_to_vtk(values.astype(np.float32), deep=True)
        a.SetName(name)
        poly.GetPointData().AddArray(a)
    poly.GetPointData().SetActiveScalars("Curvature")
    return poly


@pytest.mark.parametrize("writer", ["vtp", "vtk"])
def test_vtk_scalars_become_channels(tmp_path, writer):
    poly = curvature_sphere()
    if writer == "vtp":
        mesh = write_vtp(poly, tmp_path / "s.vtp")
    else:
        w = vtk.vtkPolyDataWriter()
        w.SetInputData(poly)
        w.SetFileName(str(tmp_path / "s.vtk"))
        kept = locale.setlocale(locale.LC_ALL)
        try:
            assert w.Write() == 1
        finally:  # VTK 9.1's legacy writer leaves the process in the C locale (ASCII text I/O for later tests)
            locale.setlocale(locale.LC_ALL, kept)
        mesh = str(tmp_path / "s.vtk")
    (tmp_path / "none.json").write_text('{"strokes": []}')
    out = paint(mesh, tmp_path / "out", tmp_path / "none.json", "--import-array", "Curvature:displacement")
    z = numpy_support.vtk_to_numpy(out.GetPoints().GetData())[:, 2]
    # roughness by its name, Curvature as asked.
    assert np.corrcoef(z, array(out, "roughness"))[0, 1] < -0.95
    assert np.corrcoef(z, array(out, "displacement"))[0, 1] > 0.95
    r = run("info", mesh, "--import-array", "Curvature:displacement")
    n = poly.GetNumberOfPoints()
    assert f"took the file's 'Curvature' array as the displacement channel ({n} vertices)" in r.stdout
    assert f"took the file's 'roughness' array as the roughness channel ({n} vertices)" in r.stdout


def test_vtk_ply_writer_colours_and_a_quality_mapping_together(tmp_path):
    """vtkPLYWriter's colours arrive as diffuse; an array it cannot write is absent, said so."""
    poly = curvature_sphere()
    colours = vtk.vtkUnsignedCharArray()
    colours.SetName("Colors")
    colours.SetNumberOfComponents(3)
    for _ in range(poly.GetNumberOfPoints()):
        colours.InsertNextTuple([255, 0, 0])
    poly.GetPointData().AddArray(colours)
    w = vtk.vtkPLYWriter()
    w.SetInputData(poly)
    w.SetArrayName("Colors")
    w.SetColorModeToDefault()
    w.SetFileName(str(tmp_path / "s.ply"))
    assert w.Write() == 1
    r = run("info", tmp_path / "s.ply")
    assert r.returncode == 0 and "took the file's colours as the diffuse channel" in r.stdout, r.stdout + r.stderr
    r = run("info", tmp_path / "s.ply", "--import-array", "Curvature:roughness")
    assert r.returncode == 2 and "has no vertex array 'Curvature'" in r.stderr, r.stderr


def test_face_properties_beside_vertex_quality_are_left_alone(tmp_path):
    """MeshLab also writes per-face quality and flags: they are no vertex arrays."""
    head = (b"ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
            b"property float z\nproperty float quality\nelement face 2\nproperty list uchar int vertex_indices\n"
            b"property float quality\nproperty int flags\nend_header\n")
    body = b"".join(struct.pack("<4f", *p) for p in [(0, 0, 0, .1), (1, 0, 0, .5), (1, 1, 0, .9), (0, 1, 0, .2)])
    body += struct.pack("<B3ifi", 3, 0, 1, 2, 0.7, 3) + struct.pack("<B3ifi", 3, 0, 2, 3, 0.2, 0)
    mesh = tmp_path / "faces.ply"
    mesh.write_bytes(head + body)
    r = run("info", mesh, "--import-array", "quality:mask")
    assert r.returncode == 0, r.stderr
    assert "counts       4 vertices, 5 edges, 2 faces" in r.stdout, r.stdout
    assert "took the file's 'quality' array as the mask channel (4 vertices)" in r.stdout
