"""Reading meshes: the variants other tools write, the import steps, and damaged files.

The files come from tests/bad_input/mesh_inputs.py (generated here, not stored),
VTK's own writers, and Geomview's OFF models where the package is installed.
"""
import glob
import json
import math
import os
import subprocess
import sys

import pytest
import vtk
from vtkmodules.util import numpy_support

BIN = os.environ["MESHPAINT_BIN"]
SOURCE = os.environ["MESHPAINT_SOURCE_DIR"]
sys.path.insert(0, os.path.join(SOURCE, "tests", "bad_input"))
import mesh_inputs  # noqa: E402

GEOMVIEW = sorted(glob.glob("/usr/share/geomview/geom/*.off"))


def run(*args):
    return subprocess.run([BIN, *args], capture_output=True, text=True, timeout=600)


def write(tmp_path, name, data):
    path = tmp_path / name
    path.write_bytes(data)
    return str(path)


def read_vtp(path):
    r = vtk.vtkXMLPolyDataReader()
    r.SetFileName(str(path))
    r.Update()
    return r.GetOutput()


@pytest.fixture(scope="module")
def project(tmp_path_factory):
    """A small project for `transfer`, fitted straight onto the cube."""
    d = tmp_path_factory.mktemp("project")
    cube = write(d, "cube.obj", mesh_inputs.obj())
    r = run("fit", cube, "--direct", "--level", "2", "-o", str(d / "cube.meshpaint"), "--quiet")
    assert r.returncode == 0, r.stderr
    return str(d / "cube.meshpaint")


@pytest.mark.parametrize("name, data, message", mesh_inputs.damaged(), ids=lambda v: v if isinstance(v, str) else "")
def test_damaged_mesh_gives_one_line_and_exit_2(tmp_path, name, data, message):
    path = write(tmp_path, name, data)
    r = run("info", path)
    lines = r.stderr.strip().splitlines()
    assert r.returncode == 2, r.stdout + r.stderr
    assert len(lines) == 1, r.stderr
    assert lines[0].startswith("meshpaint info: "), lines[0]
    import re
    assert re.search(message, lines[0]), lines[0]


@pytest.mark.parametrize("name, data, message", mesh_inputs.damaged(), ids=lambda v: v if isinstance(v, str) else "")
def test_damaged_scan_is_refused_by_transfer(tmp_path, project, name, data, message):
    path = write(tmp_path, name, data)
    out = tmp_path / "out.vtp"
    r = run("transfer", project, "--to", path, "-o", str(out), "--quiet")
    lines = r.stderr.strip().splitlines()
    assert r.returncode == 2, r.stdout + r.stderr
    assert len(lines) == 1 and lines[0].startswith("meshpaint transfer: "), r.stderr
    assert not out.exists()


def test_vtp_with_absurd_component_count_is_refused_by_transfer(tmp_path, project):
    path = tmp_path / "huge.vtp"
    path.write_text('<?xml version="1.0"?>\n<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">\n'
                    '<PolyData><Piece NumberOfPoints="1" NumberOfPolys="0"><Points>'
                    '<DataArray type="Float32" NumberOfComponents="1000000000" format="ascii">0 0 0</DataArray>'
                    '</Points></Piece></PolyData></VTKFile>\n')
    r = run("transfer", project, "--to", str(path), "-o", str(tmp_path / "o.vtp"), "--quiet")
    assert r.returncode == 2, r.stderr
    assert len(r.stderr.strip().splitlines()) == 1, r.stderr
    assert "NumberOfComponents" in r.stderr


@pytest.mark.parametrize("name, data", mesh_inputs.valid(), ids=lambda v: v if isinstance(v, str) else "")
def test_valid_variant_reads_without_repairs(tmp_path, name, data):
    path = write(tmp_path, name, data)
    r = run("info", path)
    assert r.returncode == 0, r.stderr
    assert "repaired" not in r.stderr, r.stderr
    assert "topology     1 component," in r.stdout, r.stdout


@pytest.mark.parametrize("name, data", [v for v in mesh_inputs.valid() if not v[0].startswith("4off")],
                         ids=lambda v: v if isinstance(v, str) else "")
def test_valid_variant_is_transferred_onto(tmp_path, project, name, data):
    path = write(tmp_path, name, data)
    r = run("transfer", project, "--to", path, "-o", str(tmp_path / "o.vtp"), "--quiet")
    assert r.returncode == 0, r.stderr


@pytest.mark.skipif(not GEOMVIEW, reason="Geomview's OFF models are not installed (apt-get install geomview)")
# The ids function sees pytest's placeholder where the list is empty.
@pytest.mark.parametrize("path", GEOMVIEW, ids=lambda p: os.path.basename(p) if isinstance(p, str) else "")
def test_geomview_off_models_read(path):
    r = run("info", path)
    assert r.returncode == 0, r.stderr
    assert "repaired" not in r.stderr or "hypercube" in path, r.stderr  # the 4D hypercube projects onto itself


def diffuse_of(tmp_path, mesh, *flags):
    strokes = tmp_path / "none.json"
    strokes.write_text('{"strokes": []}')
    out = tmp_path / "out"
    r = run("paint", mesh, "--strokes", str(strokes), "--level", "2", "-o", str(out), *flags)
    assert r.returncode == 0, r.stderr
    poly = read_vtp(out / "surface.vtp")
    return poly, numpy_support.vtk_to_numpy(poly.GetPointData().GetArray("diffuse"))


@pytest.mark.parametrize("name", ["coff.off", "face-colour-rgb-int.off", "geomview-binary-red-faces.off",
                                  "vertex-colours.obj", "uchar-colours.ply"])
def test_file_colours_arrive_in_the_diffuse_channel(tmp_path, name):
    data = dict(mesh_inputs.valid())[name]
    poly, diffuse = diffuse_of(tmp_path, write(tmp_path, name, data))
    if "red" in name or name == "face-colour-rgb-int.off":  # every face red
        assert abs(diffuse[:, 0].min() - 1) < 1e-5 and abs(diffuse[:, 1:]).max() < 1e-5
    else:  # each corner of the cube its own colour: the surface there is nearest to it
        import numpy as np
        colours = np.array([[(i >> b) & 1 for b in range(3)] for i in range(8)], dtype=float)
        pts = numpy_support.vtk_to_numpy(poly.GetPoints().GetData())
        for i, corner in enumerate(mesh_inputs.CUBE_POINTS):
            k = int(np.argmax((pts - pts.mean(axis=0)) @ (np.array(corner) - 0.5)))
            assert int(np.argmin(((colours - diffuse[k]) ** 2).sum(axis=1))) == i, (corner, diffuse[k])


def test_vtk_written_ply_colours_arrive_in_the_diffuse_channel(tmp_path):
    sphere = vtk.vtkSphereSource()
    sphere.SetThetaResolution(16)
    sphere.SetPhiResolution(8)
    sphere.Update()
    poly = sphere.GetOutput()
    colours = vtk.vtkUnsignedCharArray()
    colours.SetName("RGB")
    colours.SetNumberOfComponents(3)
    for i in range(poly.GetNumberOfPoints()):
        z = poly.GetPoint(i)[2]
        colours.InsertNextTuple3(255 if z > 0 else 0, 0, 255 if z <= 0 else 0)
    poly.GetPointData().SetScalars(colours)
    w = vtk.vtkPLYWriter()
    w.SetFileName(str(tmp_path / "sphere.ply"))
    w.SetInputData(poly)
    w.SetArrayName("RGB")
    w.Write()
    out, diffuse = diffuse_of(tmp_path, str(tmp_path / "sphere.ply"))
    z = numpy_support.vtk_to_numpy(out.GetPoints().GetData())[:, 2]
    assert diffuse[z > 0.3, 0].min() > 0.9 and diffuse[z < -0.3, 2].min() > 0.9


def test_counts_of_one_are_singular(tmp_path):
    quad = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (5, 5, 5)]  # the last vertex used by no face
    r = run("info", write(tmp_path, "quad.off", mesh_inputs.off(points=quad, faces=[(0, 1, 2, 3)])))
    assert r.returncode == 0, r.stderr
    assert "4 vertices, 4 edges, 1 face (1 quad)\n" in r.stdout, r.stdout
    assert "boundaries   1 loop, 4 edges\n" in r.stdout, r.stdout
    assert "removed 1 vertex used by no face" in r.stdout, r.stdout


@pytest.mark.parametrize("binary", [False, True], ids=["ascii", "binary"])
def test_stl_gets_the_uniform_default_diffuse(tmp_path, binary):
    """STL carries no colours: nothing may be taken as the file's colours."""
    sphere = vtk.vtkSphereSource()
    sphere.Update()
    w = vtk.vtkSTLWriter()
    w.SetFileName(str(tmp_path / "sphere.stl"))
    w.SetInputData(sphere.GetOutput())
    if binary:
        w.SetFileTypeToBinary()
    else:
        w.SetFileTypeToASCII()
    w.Write()
    strokes = tmp_path / "none.json"
    strokes.write_text('{"strokes": []}')
    r = run("paint", str(tmp_path / "sphere.stl"), "--strokes", str(strokes), "--level", "1", "-o", str(tmp_path / "out"))
    assert r.returncode == 0, r.stderr
    assert "colours" not in r.stderr, r.stderr
    diffuse = numpy_support.vtk_to_numpy(read_vtp(tmp_path / "out" / "surface.vtp").GetPointData().GetArray("diffuse"))
    assert (diffuse == diffuse[0]).all(), diffuse[:4]


@pytest.mark.parametrize("writer", ["stl", "obj", "off-soup"])
def test_a_soup_becomes_one_component(tmp_path, writer):
    if writer == "off-soup":
        pts, faces = mesh_inputs.soup_of(mesh_inputs.CUBE_POINTS, mesh_inputs.CUBE_QUADS)
        path = write(tmp_path, "soup.off", mesh_inputs.off(points=pts, faces=faces))
    else:
        pts, faces = mesh_inputs.soup_of(mesh_inputs.CUBE_POINTS, mesh_inputs.CUBE_TRIANGLES)
        poly = vtk.vtkPolyData()
        points = vtk.vtkPoints()
        for p in pts:
            points.InsertNextPoint(p)
        cells = vtk.vtkCellArray()
        for f in faces:
            cells.InsertNextCell(len(f), f)
        poly.SetPoints(points)
        poly.SetPolys(cells)
        path = str(tmp_path / f"soup.{writer}")
        w = vtk.vtkSTLWriter() if writer == "stl" else vtk.vtkOBJWriter()
        w.SetFileName(path)
        w.SetInputData(poly)
        w.Write()
    r = run("info", path)
    assert r.returncode == 0, r.stderr
    assert "topology     1 component, genus 0" in r.stdout, r.stdout
    if writer != "stl":  # VTK's STL reader... no: OpenMesh's STL reader welds itself
        assert "welded" in r.stdout
        kept = run("info", path, "--no-weld")
        assert kept.returncode == 0 and "topology     6 components" in kept.stdout or \
            "topology     12 components" in kept.stdout, kept.stdout


def sphere_mesh(resolution=8):
    """A closed triangulated sphere about the origin (vertices on the axes' planes)."""
    sphere = vtk.vtkSphereSource()
    sphere.SetThetaResolution(resolution)
    sphere.SetPhiResolution(resolution)
    sphere.Update()
    poly = sphere.GetOutput()
    pts = [poly.GetPoint(i) for i in range(poly.GetNumberOfPoints())]
    ids = numpy_support.vtk_to_numpy(poly.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    return pts, [tuple(int(i) for i in f) for f in ids]


def test_a_soup_jittered_within_the_weld_tolerance_becomes_one_component(tmp_path):
    # Copies 1e-8 of the diagonal apart, on either side of the coordinate
    # planes the sphere's poles and seams lie on: no grid of cells may part them.
    import random
    pts, faces = mesh_inputs.soup_of(*sphere_mesh())
    rnd = random.Random(3)
    jittered = [tuple(c + rnd.choice((-1, 1)) * 1e-8 for c in p) for p in pts]
    path = write(tmp_path, "jittered.obj", mesh_inputs.obj(points=jittered, faces=faces))
    r = run("info", path)
    assert r.returncode == 0, r.stderr
    assert "topology     1 component, genus 0" in r.stdout, r.stdout
    assert "cut" not in r.stdout, r.stdout


def test_inner_vertices_closer_than_the_tolerance_are_not_welded(tmp_path):
    # A dense scan can hold distinct neighbouring vertices closer than the
    # weld tolerance; joining them would tear the surface.
    pts, faces = sphere_mesh()
    i, j = faces[5][0], faces[5][1]
    pts[j] = tuple(a + 1e-7 * (b - a) for a, b in zip(pts[i], pts[j]))
    path = write(tmp_path, "close.off", mesh_inputs.off(points=pts, faces=faces))
    r = run("info", path)
    assert r.returncode == 0, r.stderr
    assert "import       no repairs" in r.stdout, r.stdout
    assert f"counts       {len(pts)} vertices" in r.stdout, r.stdout


def signed_volume(poly):
    tri = vtk.vtkTriangleFilter()
    tri.SetInputData(poly)
    tri.Update()
    t = tri.GetOutput()
    pts = numpy_support.vtk_to_numpy(t.GetPoints().GetData()).astype(float)
    ids = numpy_support.vtk_to_numpy(t.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    a, b, c = pts[ids[:, 0]], pts[ids[:, 1]], pts[ids[:, 2]]
    return float((a * ((b[:, [1, 2, 0]] * c[:, [2, 0, 1]]) - (b[:, [2, 0, 1]] * c[:, [1, 2, 0]]))).sum() / 6)


def test_an_inward_wound_closed_scan_gets_outward_limit_normals(tmp_path):
    scan = os.path.join(SOURCE, "data", "scans", "bunny00.off")
    if not os.path.exists(scan):
        pytest.skip("the scans are not installed (scripts/fetch-scans.sh)")
    lines = open(scan).read().splitlines()
    nv, nf = (int(x) for x in lines[1].split()[:2])
    for k in range(2 + nv, 2 + nv + nf):
        w = lines[k].split()
        lines[k] = " ".join([w[0]] + w[1:][::-1])
    inward = tmp_path / "inward.off"
    inward.write_text("\n".join(lines) + "\n")
    out = tmp_path / "limit.vtp"
    r = run("subdivide", str(inward), "--level", "1", "--limit", "-o", str(out))
    assert r.returncode == 0, r.stderr
    assert "turned 1 closed component wound inwards outward" in r.stderr
    poly = read_vtp(out)
    assert signed_volume(poly) > 0
    pts = numpy_support.vtk_to_numpy(poly.GetPoints().GetData())
    normals = numpy_support.vtk_to_numpy(poly.GetPointData().GetArray("Normals"))
    centre = pts.mean(axis=0)
    # Most normals point away from the centre on this roughly convex scan.
    assert ((normals * (pts - centre)).sum(axis=1) > 0).mean() > 0.8


def test_meshpaint_reads_its_own_vtp_output_with_its_colours(tmp_path):
    data = dict(mesh_inputs.valid())["coff.off"]
    poly, diffuse = diffuse_of(tmp_path, write(tmp_path, "coff.off", data))
    again = tmp_path / "again"
    again.mkdir()
    back, diffuse_back = diffuse_of(again, str(tmp_path / "out" / "surface.vtp"))
    r = run("info", str(tmp_path / "out" / "surface.vtp"))
    assert r.returncode == 0, r.stderr
    assert f"took the file's 'diffuse' array as the diffuse channel ({poly.GetNumberOfPoints()} vertices)" in r.stdout
    # Its label array holds zeros only (nothing labelled): unlabelled, no class.
    assert "label channel" not in r.stdout + r.stderr
    # The read-back surface starts from the painted one's colours: the same range.
    assert abs(diffuse_back.max() - diffuse.max()) < 0.1 and abs(diffuse_back.min() - diffuse.min()) < 0.1


def test_legacy_vtk_polydata_reads(tmp_path):
    sphere = vtk.vtkSphereSource()
    sphere.Update()
    w = vtk.vtkPolyDataWriter()
    w.SetFileName(str(tmp_path / "sphere.vtk"))
    w.SetInputData(sphere.GetOutput())
    w.Write()
    r = run("info", str(tmp_path / "sphere.vtk"))
    assert r.returncode == 0, r.stderr
    assert "topology     1 component, genus 0" in r.stdout


@pytest.mark.parametrize("name, text, message", [
    ("huge.vtk", "# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\nPOINTS 2000000000 float\n0 0 0\n",
     "POINTS 2000000000 float: 2000000000 tuples are more than the file can hold"),
    ("nan.vtk", "# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n0 0 0 1 0 0 0 nan 0\n"
     "POLYGONS 1 4\n3 0 1 2\n", "value 8 is 'nan', not a float"),
    ("missing-point.vtk", "# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n0 0 0 1 0 0 0 1 0\n"
     "POLYGONS 1 4\n3 0 1 7\n", "names point 7|cannot read"),
    ("components.vtp", '<?xml version="1.0"?>\n<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">\n'
     '<PolyData><Piece NumberOfPoints="1" NumberOfPolys="0"><Points><DataArray type="Float32" '
     'NumberOfComponents="1000000000" format="ascii">0 0 0</DataArray></Points></Piece></PolyData></VTKFile>\n',
     "NumberOfComponents=\"1000000000\" is more than the file can hold"),
    ("truncated.vtp", '<?xml version="1.0"?>\n<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">\n'
     '<PolyData><Piece NumberOfPoints="3" NumberOfPolys="1"><Points><DataArray type="Float32" ', "cannot read"),
])
def test_damaged_vtk_files_give_one_line(tmp_path, name, text, message):
    path = tmp_path / name
    path.write_text(text)
    r = run("info", str(path))
    lines = r.stderr.strip().splitlines()
    assert r.returncode == 2, r.stdout + r.stderr
    assert len(lines) == 1, r.stderr
    import re
    assert re.search(message, lines[0]), lines[0]


def test_a_scan_wound_every_which_way_paints_every_dab_in_screen_and_tangent_space(tmp_path):
    """Every other face of a sphere turned over: the import turns them to
    agree, so a screen brush and a tangent brush land every dab where the
    path goes, on the side the camera sees."""
    sphere = vtk.vtkSphereSource()
    sphere.SetThetaResolution(40)
    sphere.SetPhiResolution(40)
    sphere.Update()
    poly = sphere.GetOutput()
    lines = ["v %r %r %r" % poly.GetPoint(i) for i in range(poly.GetNumberOfPoints())]
    ids = numpy_support.vtk_to_numpy(poly.GetPolys().GetConnectivityArray()).reshape(-1, 3) + 1
    for k, face in enumerate(ids):
        corners = face[::-1] if k % 2 == 0 else face
        lines.append("f %d %d %d" % tuple(corners))
    mesh = tmp_path / "every-which-way.obj"
    mesh.write_text("\n".join(lines) + "\n")
    path = [[-0.3, 0, 0.4], [0, 0.05, 0.5], [0.3, 0.1, 0.4]]
    script = tmp_path / "strokes.json"
    script.write_text(json.dumps({"strokes": [
        {"tool": "paint", "space": "screen", "points": path, "radius": 0.08, "channels": {"diffuse": [1, 0, 0]},
         "camera": {"position": [0, 0, 5], "focal_point": [0, 0, 0], "view_up": [0, 1, 0]}},
        {"tool": "paint", "space": "tangent", "points": path, "radius": 0.08, "channels": {"diffuse": [0, 1, 0]}}]}))
    r = run("paint", str(mesh), "--strokes", str(script), "--level", "2", "-o", str(tmp_path / "out"), "--quiet")
    assert r.returncode == 0, r.stderr
    assert f"turned {len(ids) // 2} faces to agree with their neighbours" in r.stderr
    rows = [line.split() for line in r.stdout.splitlines() if line.split()[:2] in (["0", "paint"], ["1", "paint"])]
    assert len(rows) == 2, r.stdout
    for row in rows:
        dabs, on_surface = int(row[2]), int(row[3])
        assert dabs > 10 and on_surface == dabs, r.stdout


def label_grid():
    """A 2x2 grid of quads in z=0, as a soup (every quad its own 4 corners);
    the corners at x <= 1 are labelled 3, those at x = 2 labelled 7."""
    points, faces = [], []
    for y in range(2):
        for x in range(2):
            corners = [(x, y), (x + 1, y), (x + 1, y + 1), (x, y + 1)]
            faces.append(list(range(len(points), len(points) + 4)))
            points += [(cx, cy, 0.0) for cx, cy in corners]
    labels = [3 if p[0] <= 1 else 7 for p in points]
    return points, faces, labels


def label_ply(name, kind, binary=False):
    import struct
    points, faces, labels = label_grid()
    text = (f"ply\nformat {'binary_little_endian' if binary else 'ascii'} 1.0\nelement vertex {len(points)}\nproperty float x\nproperty float y\n"
            f"property float z\nproperty {kind} {name}\nelement face {len(faces)}\n"
            "property list uchar int vertex_indices\nend_header\n")
    if binary:
        code = {"int": "<i", "uchar": "<B", "short": "<h"}[kind]
        body = b"".join(struct.pack("<3f", *p) + struct.pack(code, l) for p, l in zip(points, labels))
        body += b"".join(struct.pack("<B4i", 4, *f) for f in faces)
        return text.encode() + body
    text += "".join(f"{p[0]} {p[1]} {p[2]} {l}\n" for p, l in zip(points, labels))
    text += "".join("4 " + " ".join(map(str, f)) + "\n" for f in faces)
    return text.encode()


def label_vtp(tmp_path, array_type):
    points, faces, labels = label_grid()
    poly = vtk.vtkPolyData()
    pts = vtk.vtkPoints()
    for p in points:
        pts.InsertNextPoint(p)
    poly.SetPoints(pts)
    cells = vtk.vtkCellArray()
    for f in faces:
        cells.InsertNextCell(len(f), f)
    poly.SetPolys(cells)
    ids = array_type()
    ids.SetName("label")
    for l in labels:
        ids.InsertNextValue(l)
    poly.GetPointData().AddArray(ids)
    w = vtk.vtkXMLPolyDataWriter()
    w.SetFileName(str(tmp_path / "grid.vtp"))
    w.SetInputData(poly)
    assert w.Write() == 1
    return str(tmp_path / "grid.vtp")


def check_label_channel(tmp_path, mesh, array):
    """The label channel of `paint` has only the file's ids, each where its
    vertices are, and the import says which array it took."""
    import numpy as np
    info = run("info", mesh)
    assert info.returncode == 0, info.stderr
    assert f"took the file's '{array}' array as the label channel (2 classes)" in info.stdout, info.stdout
    poly, _ = diffuse_of(tmp_path, mesh)
    label = numpy_support.vtk_to_numpy(poly.GetPointData().GetArray("label"))
    x = numpy_support.vtk_to_numpy(poly.GetPoints().GetData())[:, 0]
    assert set(np.unique(label).tolist()) == {3, 7}
    assert (label[x < 1.25] == 3).all() and (label[x > 1.75] == 7).all()
    stats = run("stats", mesh, "--json")
    assert stats.returncode == 0, stats.stderr
    assert f"imported: took the file's '{array}' array as the label channel (2 classes)" in stats.stderr
    import json
    rows = {row["id"]: row for row in json.loads(stats.stdout)["labels"]}
    assert sorted(rows) == [3, 7] and rows[7]["name"] == "label 7" and rows[7]["colour"] is not None
    # The x = 2 column's label holds about the quarter of the grid nearest to it.
    assert 0.15 < rows[7]["area_fraction"] < 0.35, rows[7]


@pytest.mark.parametrize("binary", [False, True])
@pytest.mark.parametrize("name, kind", [("label", "int"), ("class", "uchar"), ("segment", "short")])
def test_ply_label_property_becomes_the_label_channel(tmp_path, name, kind, binary):
    check_label_channel(tmp_path, write(tmp_path, "grid.ply", label_ply(name, kind, binary)), name)


@pytest.mark.parametrize("array_type", [vtk.vtkIntArray, vtk.vtkUnsignedCharArray])
def test_vtp_label_array_becomes_the_label_channel(tmp_path, array_type):
    check_label_channel(tmp_path, label_vtp(tmp_path, array_type), "label")


def test_float_label_property_is_not_taken_as_labels(tmp_path):
    r = run("info", write(tmp_path, "grid.ply", label_ply("label", "float")))
    assert r.returncode == 0, r.stderr
    assert "label channel" not in r.stdout


def test_negative_label_is_refused(tmp_path):
    data = label_ply("label", "int").replace(b"0.0 3\n", b"0.0 -3\n", 1)
    r = run("info", write(tmp_path, "grid.ply", data))
    assert r.returncode == 2 and "has label -3, outside 0 to 16777216" in r.stderr, r.stderr


POLYDATA_FINDINGS = sorted(glob.glob(os.path.join(SOURCE, "tests", "fuzz", "regressions", "fuzz_polydata_*", "*")))


@pytest.mark.parametrize("path", POLYDATA_FINDINGS, ids=os.path.basename)
def test_polydata_fuzz_findings_are_bad_input(tmp_path, path):
    # As the fuzz targets read them: the bytes under their format's extension.
    mesh = tmp_path / ("finding" + (".vtp" if "fuzz_polydata_vtp" in path else ".vtk"))
    mesh.write_bytes(open(path, "rb").read())
    r = run("info", str(mesh))
    lines = r.stderr.strip().splitlines()
    assert r.returncode == 2, r.stdout + r.stderr
    assert len(lines) == 1 and lines[0].startswith("meshpaint info: "), r.stderr


def sphere_with_field_array(array, path, binary):
    """A VTK sphere with `array` in its field data, written as legacy .vtk."""
    s = vtk.vtkSphereSource()
    s.Update()
    poly = s.GetOutput()
    poly.GetFieldData().AddArray(array)
    w = vtk.vtkPolyDataWriter()
    w.SetInputData(poly)
    w.SetFileType(2 if binary else 1)
    w.SetFileName(str(path))
    w.Write()


def weights_array():
    """A field array of 4 float triples named weights (header `weights 3 4 float`)."""
    values = vtk.vtkFloatArray()
    values.SetName("weights")
    values.SetNumberOfComponents(3)
    for k in range(4):
        values.InsertNextTuple3(k, k + 0.5, k + 0.25)
    return values


@pytest.mark.parametrize("binary", [False, True])
def test_legacy_string_arrays_are_read_only_as_text(tmp_path, binary):
    # VTK's legacy reader trusts the string lengths stored in binary data.
    names = vtk.vtkStringArray()
    names.SetName("names")
    names.InsertNextValue("scan")
    sphere_with_field_array(names, tmp_path / "s.vtk", binary)
    r = run("info", str(tmp_path / "s.vtk"))
    if not binary:
        assert r.returncode == 0, r.stderr
    else:
        assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1, r.stderr
        assert "binary string array" in r.stderr, r.stderr


def test_a_repeated_legacy_cell_section_is_refused(tmp_path):
    text = open(os.path.join(SOURCE, "tests", "fuzz", "corpus", "fuzz_polydata_vtk", "cube-ascii.vtk")).read()
    start = text.index("POLYGONS")
    end = text.index("POINT_DATA")
    path = tmp_path / "twice.vtk"
    path.write_text(text[:end] + text[start:])
    r = run("info", str(path))
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1, r.stderr
    assert "repeats the section" in r.stderr, r.stderr


@pytest.mark.parametrize("where", ["before POINTS", "after POLYGONS"])
@pytest.mark.parametrize("binary", [False, True])
def test_unreadable_dataset_field_data_is_refused_and_readable_field_data_read(tmp_path, where, binary):
    # VTK's legacy reader deletes the null result of field data it could not
    # read in the dataset section; such a file must be refused with one line,
    # and field data that reads (label classes travel in it) must still load.
    sphere_with_field_array(weights_array(), tmp_path / "good.vtk", binary)
    good = (tmp_path / "good.vtk").read_bytes()
    assert run("info", str(tmp_path / "good.vtk")).returncode == 0
    # The writer puts field data before POINTS; move it if asked.
    start = good.index(b"FIELD FieldData 1")
    end = good.index(b"POINTS")
    block = good[start:end]
    body = good[:start] + good[end:]
    if where == "after POLYGONS":
        at = body.index(b"POINT_DATA") if b"POINT_DATA" in body else len(body)
        body = body[:at] + block + body[at:]
    else:
        body = body[:start] + block + body[start:]
    (tmp_path / "moved.vtk").write_bytes(body)
    r = run("info", str(tmp_path / "moved.vtk"))
    assert r.returncode == 0, r.stderr
    # Damage the block: an array header that cannot be read.
    damaged = body.replace(b"weights 3 4 float", b"weights 3 x float")
    assert damaged != body
    (tmp_path / "damaged.vtk").write_bytes(damaged)
    r = run("info", str(tmp_path / "damaged.vtk"))
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1, r.stderr
    assert "the FIELD array weights is 'x', not a count" in r.stderr, r.stderr


@pytest.mark.parametrize("header", [b"weights 3 4string", b"weights 3 4\nstring", b"weights 3\n4 string"])
def test_a_binary_string_type_is_refused_however_its_words_are_laid_out(tmp_path, header):
    # VTK's legacy reader reads words, not lines: a string type run into its
    # count or moved to the next line is still a string array, whose lengths
    # its reader trusts.
    sphere_with_field_array(weights_array(), tmp_path / "good.vtk", True)
    body = (tmp_path / "good.vtk").read_bytes()
    assert b"weights 3 4 float" in body
    (tmp_path / "bad.vtk").write_bytes(body.replace(b"weights 3 4 float", header))
    r = run("info", str(tmp_path / "bad.vtk"))
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1, r.stderr
    # Run into its count, the type makes the count no count.
    expected = "'4string', not a count" if header == b"weights 3 4string" else "binary string array"
    assert expected in r.stderr, r.stderr


def sphere_with_every_attribute():
    """A sphere carrying every kind of attribute VTK's legacy writer writes,
    with component names and array information (METADATA blocks)."""
    s = vtk.vtkSphereSource()
    s.Update()
    poly = vtk.vtkPolyData()
    poly.DeepCopy(s.GetOutput())
    n = poly.GetNumberOfPoints()
    cells = poly.GetNumberOfCells()

    def array(cls, name, components, count, value=lambda i, c: (i + c) % 7):
        a = cls()
        a.SetName(name)
        a.SetNumberOfComponents(components)
        a.SetNumberOfTuples(count)
        for i in range(count):
            for c in range(components):
                a.SetComponent(i, c, value(i, c))
        return a

    pd, cd = poly.GetPointData(), poly.GetCellData()
    scalars = array(vtk.vtkFloatArray, "height", 2, n)
    scalars.SetComponentName(0, "first")
    scalars.SetComponentName(1, "second")
    scalars.GetInformation().Set(vtk.vtkDataArray.UNITS_LABEL(), "mm")
    pd.SetScalars(scalars)
    lut = vtk.vtkLookupTable()
    lut.SetNumberOfTableValues(4)
    lut.Build()
    scalars.SetLookupTable(lut)
    pd.SetVectors(array(vtk.vtkDoubleArray, "flow", 3, n))
    pd.SetTCoords(array(vtk.vtkFloatArray, "uv", 2, n, lambda i, c: 0.5))
    pd.SetTensors(array(vtk.vtkFloatArray, "stress", 9, n))
    pd.SetGlobalIds(array(vtk.vtkIdTypeArray, "gid", 1, n, lambda i, c: i))
    pd.AddArray(array(vtk.vtkShortArray, "shorts", 1, n))
    pd.AddArray(array(vtk.vtkUnsignedIntArray, "uints", 1, n))
    pd.AddArray(array(vtk.vtkTypeInt64Array, "int64s", 1, n))
    pd.AddArray(array(vtk.vtkCharArray, "chars", 1, n))
    pd.AddArray(array(vtk.vtkBitArray, "bits", 1, n, lambda i, c: i % 2))
    cd.SetScalars(array(vtk.vtkUnsignedCharArray, "colour", 3, cells, lambda i, c: 40 * c))
    cd.SetPedigreeIds(array(vtk.vtkIntArray, "pid", 1, cells, lambda i, c: i))
    names = vtk.vtkStringArray()
    names.SetName("label_names")
    names.InsertNextValue("left lobe")
    names.InsertNextValue("")
    poly.GetFieldData().AddArray(names)
    return poly


@pytest.mark.parametrize("version", [42, 51])
@pytest.mark.parametrize("binary", [False, True])
def test_every_attribute_vtks_legacy_writer_writes_reads(tmp_path, version, binary):
    poly = sphere_with_every_attribute()
    if binary:
        # Binary string arrays are refused (their lengths are trusted).
        poly.GetFieldData().RemoveArray("label_names")
    w = vtk.vtkPolyDataWriter()
    w.SetInputData(poly)
    w.SetFileType(2 if binary else 1)
    w.SetFileVersion(version)
    w.SetFileName(str(tmp_path / "every.vtk"))
    assert w.Write() == 1
    text = (tmp_path / "every.vtk").read_bytes()
    assert b"METADATA" in text and b"LOOKUP_TABLE" in text
    r = run("info", str(tmp_path / "every.vtk"))
    assert r.returncode == 0, r.stderr
    assert "topology     1 component, genus 0" in r.stdout


def legacy_sphere(tmp_path, binary=False):
    sphere_with_field_array(weights_array(), tmp_path / "good.vtk", binary)
    return (tmp_path / "good.vtk").read_bytes()


@pytest.mark.parametrize("name, change, message", [
    # VTK's reader spins for ever on 256 spaces after an array.
    ("spaces", lambda t: t.replace(b"\nPOLYGONS", b"\n" + b" " * 300 + b"\nPOLYGONS", 1),
     "a run of 256 spaces or more"),
    # It recurses on each repeat of point and cell data (the sphere has point data).
    ("twice", lambda t: t + b"CELL_DATA 96\nCELL_DATA 96\n", "CELL_DATA repeats"),
    ("count", lambda t: t + b"CELL_DATA 95\n", "CELL_DATA 95 for 96 cells"),
    # It scales ASCII colours to bytes without clamping them.
    ("colour", lambda t: t + b"CELL_DATA 96\nCOLOR_SCALARS c 1\n" + b"0.5 " * 95 + b"7\n",
     "value 96 is '7', not a colour value from 0 to 1"),
    ("word", lambda t: t + b"CELL_DATA 96\nSCALARS s float\nLOOKUP_TABLE default\n" + b"1 " * 95 + b"1e\n",
     "value 96 is '1e', not a float"),
    ("range", lambda t: t + b"CELL_DATA 96\nSCALARS s short\nLOOKUP_TABLE default\n" + b"1 " * 95 + b"40000\n",
     "value 96 is '40000', beyond the range of short"),
    ("keyword", lambda t: t + b"CELL_DATA 96\nEDGE_FLAGS e int\n", "'EDGE_FLAGS' is not an attribute of cells"),
])
def test_legacy_files_vtks_reader_mishandles_are_refused_by_line(tmp_path, name, change, message):
    text = change(legacy_sphere(tmp_path))
    (tmp_path / "bad.vtk").write_bytes(text)
    r = run("info", str(tmp_path / "bad.vtk"))
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1, r.stderr
    assert message in r.stderr and ": line " in r.stderr, r.stderr


def test_binary_legacy_data_must_start_on_the_next_line(tmp_path):
    text = legacy_sphere(tmp_path, binary=True)
    assert b"POINTS 50 float\n" in text
    (tmp_path / "bad.vtk").write_bytes(text.replace(b"POINTS 50 float\n", b"POINTS 50 float junk\n"))
    r = run("info", str(tmp_path / "bad.vtk"))
    assert r.returncode == 2 and "its binary data starts on the next line" in r.stderr, r.stderr
    (tmp_path / "short.vtk").write_bytes(text[:text.index(b"POINTS 50 float\n") + 100])
    r = run("info", str(tmp_path / "short.vtk"))
    assert r.returncode == 2 and "600 bytes of binary data" in r.stderr, r.stderr


@pytest.mark.parametrize("binary", [False, True])
def test_legacy_vtk_scans_are_transferred_onto_and_damaged_ones_refused(tmp_path, project, binary):
    cube = vtk.vtkCubeSource()
    cube.Update()
    tri = vtk.vtkTriangleFilter()
    tri.SetInputData(cube.GetOutput())
    tri.Update()
    scan = tri.GetOutput()
    w = vtk.vtkPolyDataWriter()
    w.SetInputData(scan)
    w.SetFileType(2 if binary else 1)
    w.SetFileName(str(tmp_path / "scan.vtk"))
    assert w.Write() == 1
    out = tmp_path / "o.vtp"
    r = run("transfer", project, "--to", str(tmp_path / "scan.vtk"), "-o", str(out), "--quiet")
    assert r.returncode == 0, r.stderr
    got = read_vtp(out)
    assert got.GetNumberOfPoints() == scan.GetNumberOfPoints() and got.GetPointData().GetArray("label") is not None
    # The scan's own arrays come along (the cube's normals and texture coordinates).
    assert got.GetPointData().GetArray("Normals") is not None
    (tmp_path / "bad.vtk").write_bytes((tmp_path / "scan.vtk").read_bytes() + b"POINT_DATA 24\n")
    r = run("transfer", project, "--to", str(tmp_path / "bad.vtk"), "-o", str(tmp_path / "b.vtp"), "--quiet")
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1, r.stderr
    assert "POINT_DATA repeats" in r.stderr and not (tmp_path / "b.vtp").exists(), r.stderr
