"""What meshpaint writes, as other tools read it (PLY colours and labels, VTP
label classes, glTF, MTL), and how it writes: atomically, on a full disk, with
temporaries of killed runs, and with several runs continuing one project.
Run by CTest like test_cli.py."""
import json
import os
import shutil
import struct
import subprocess

import pytest
import vtk
from vtkmodules.util import numpy_support

from test_cli import BIN, PLANE_OBJ, read_polydata, run
from test_project import read_ply, history_length

LABELS = [{"id": 1, "name": "bone", "colour": [1, 0.5, 0]}, {"id": 4, "name": "tumour", "colour": [0.2, 0.2, 1]}]


@pytest.fixture
def plane(tmp_path):
    path = tmp_path / "plane.obj"
    path.write_text(PLANE_OBJ)
    return path


def script(tmp_path, name, strokes, level=3):
    path = tmp_path / name
    path.write_text(json.dumps({"strokes": strokes, "level": level}))
    return path


def everywhere(**channels):
    """A stroke covering the whole 4 x 4 plane at full strength."""
    return {"tool": "paint", "points": [[2, 2, 0]], "radius": 10, "falloff": "constant", "channels": channels}


PAINT = [{"tool": "paint", "points": [[1, 1, 0], [3, 1, 0]], "radius": 0.5, "falloff": "constant",
          "channels": {"diffuse": [1, 0.25, 0]}},
         {"tool": "label", "points": [[2, 3, 0]], "radius": 0.6, "falloff": "constant", "channels": {"label": 4}}]


@pytest.fixture
def project(plane, tmp_path):
    """The plane painted red at its bottom and labelled 4 at its top, with label classes."""
    labels = tmp_path / "labels.json"
    labels.write_text(json.dumps(LABELS))
    path = tmp_path / "p.meshpaint"
    r = run("paint", str(plane), "--strokes", str(script(tmp_path, "s.json", PAINT)), "--labels", str(labels),
            "--save", str(path), "-o", str(tmp_path / "out"), "--quiet")
    assert r.returncode == 0, r.stderr
    return path


def write_vtp(poly, path):
    writer = vtk.vtkXMLPolyDataWriter()
    writer.SetFileName(str(path))
    writer.SetInputData(poly)
    assert writer.Write() == 1


# ---------------------------------------------------------------- formats


def test_transfer_ply_has_uchar_colours_and_an_int_label(project, plane, tmp_path):
    r = run("transfer", str(project), "--to", str(plane), "-o", str(tmp_path / "o.ply"), "--quiet")
    assert r.returncode == 0, r.stderr
    header = (tmp_path / "o.ply").read_bytes().split(b"end_header")[0].decode()
    for line in ("property uchar red", "property uchar green", "property uchar blue", "property int label"):
        assert line in header.splitlines(), header
    vertices, _ = read_ply(tmp_path / "o.ply")
    # the colours are the diffuse floats (kept beside them) in bytes
    for k in range(len(vertices)):
        for c, name in zip("rgb", ("red", "green", "blue")):
            assert vertices[name][k] == int(vertices["diffuse_" + c][k] * 255 + 0.5), (k, name)
    assert (vertices["red"][6], vertices["green"][6], vertices["blue"][6]) == (255, 64, 0)
    assert set(vertices["label"]) == {0, 4}
    # VTK's PLY reader, as other tools, takes red/green/blue as the colours
    reader = vtk.vtkPLYReader()
    reader.SetFileName(str(tmp_path / "o.ply"))
    reader.Update()
    rgb = reader.GetOutput().GetPointData().GetArray("RGB")
    assert rgb.GetDataType() == vtk.VTK_UNSIGNED_CHAR and rgb.GetNumberOfComponents() == 3
    assert rgb.GetTuple3(6) == (255, 64, 0)


def test_transfer_ply_keeps_a_non_manifold_scan_as_it_is(project, tmp_path):
    # a fin on an inner edge of the plane: three faces at one edge
    scan = tmp_path / "fin.obj"
    scan.write_text(PLANE_OBJ + "v 1.5 1 1\nf 7 8 26\n")
    r = run("transfer", str(project), "--to", str(scan), "-o", str(tmp_path / "o.ply"), "--quiet")
    assert r.returncode == 0, r.stderr
    reader = vtk.vtkPLYReader()
    reader.SetFileName(str(tmp_path / "o.ply"))
    reader.Update()
    out = reader.GetOutput()
    assert (out.GetNumberOfPoints(), out.GetNumberOfPolys()) == (26, 17)
    corners = vtk.vtkIdList()
    out.GetCellPoints(16, corners)
    assert [corners.GetId(k) for k in range(3)] == [6, 7, 25]
    vertices, _ = read_ply(tmp_path / "o.ply")
    assert len(vertices["label"]) == 26


def label_classes(poly):
    fd = poly.GetFieldData()
    ids, names, colours = (fd.GetAbstractArray(n) for n in ("label_ids", "label_names", "label_colors"))
    assert ids.GetDataType() == vtk.VTK_INT and ids.GetNumberOfComponents() == 1
    assert names.GetClassName() == "vtkStringArray"
    assert colours.GetDataType() == vtk.VTK_UNSIGNED_CHAR and colours.GetNumberOfComponents() == 3
    return ([ids.GetValue(k) for k in range(ids.GetNumberOfTuples())],
            [names.GetValue(k) for k in range(names.GetNumberOfValues())],
            [colours.GetTuple3(k) for k in range(colours.GetNumberOfTuples())])


EXPECTED_CLASSES = ([1, 4], ["bone", "tumour"], [(255, 128, 0), (51, 51, 255)])


def test_surface_vtp_and_transfer_vtp_carry_the_label_classes(project, plane, tmp_path):
    assert label_classes(read_polydata(tmp_path / "out" / "surface.vtp")) == EXPECTED_CLASSES
    r = run("transfer", str(project), "--to", str(plane), "-o", str(tmp_path / "o.vtp"), "--quiet")
    assert r.returncode == 0, r.stderr
    assert label_classes(read_polydata(tmp_path / "o.vtp")) == EXPECTED_CLASSES
    # a project continued without --labels keeps its classes in its outputs
    r = run("paint", str(project), "--strokes", str(script(tmp_path, "none.json", [])), "-o", str(tmp_path / "again"),
            "--quiet")
    assert r.returncode == 0, r.stderr
    assert label_classes(read_polydata(tmp_path / "again" / "surface.vtp")) == EXPECTED_CLASSES


def test_a_mesh_without_labels_gives_empty_label_arrays(plane, tmp_path):
    r = run("paint", str(plane), "--strokes", str(script(tmp_path, "s.json", PAINT)), "-o", str(tmp_path / "o"))
    assert r.returncode == 0, r.stderr
    assert label_classes(read_polydata(tmp_path / "o" / "surface.vtp")) == ([], [], [])


def mtl_values(path, material="painted"):
    values, current = {}, None
    for line in path.read_text().splitlines():
        words = line.split()
        if words and words[0] == "newmtl":
            current = words[1]
        elif words and current == material and words[0] in ("Ks", "Ns"):
            values[words[0]] = [float(w) for w in words[1:]]
    return values


@pytest.mark.parametrize("specular, roughness", [([0.5, 0.25, 0.125], 0.3), ([0.04, 0.04, 0.04], 0.8)])
def test_mtl_ks_and_ns_follow_the_painted_specular_and_roughness(plane, tmp_path, specular, roughness):
    strokes = script(tmp_path, "s.json", [everywhere(specular=specular, roughness=roughness)])
    r = run("paint", str(plane), "--strokes", str(strokes), "-o", str(tmp_path / "o"), "--quiet")
    assert r.returncode == 0, r.stderr
    values = mtl_values(tmp_path / "o" / "model.mtl")
    assert values["Ks"] == pytest.approx(specular, abs=1e-5)
    alpha = roughness ** 2
    assert values["Ns"][0] == pytest.approx(min(1000.0, 2 / alpha ** 2 - 2), rel=1e-4)


def png_pixels(data=None, path=None):
    reader = vtk.vtkPNGReader()
    if path is not None:
        reader.SetFileName(str(path))
    else:
        reader.SetMemoryBuffer(data)
        reader.SetMemoryBufferLength(len(data))
    reader.Update()
    image = reader.GetOutput()
    return image.GetDimensions(), numpy_support.vtk_to_numpy(image.GetPointData().GetScalars()).tolist()


def gltf_document(path):
    """The JSON of a .gltf or .glb, and the bytes of its first buffer."""
    import base64
    data = path.read_bytes()
    if path.suffix == ".glb":
        assert data[:4] == b"glTF" and struct.unpack_from("<I", data, 4)[0] == 2
        json_length = struct.unpack_from("<I", data, 12)[0]
        doc = json.loads(data[20:20 + json_length])
        at = 20 + json_length
        bin_length = struct.unpack_from("<I", data, at)[0]
        return doc, data[at + 8:at + 8 + bin_length]
    doc = json.loads(data)
    uri = doc["buffers"][0]["uri"]
    return doc, base64.b64decode(uri.split(",", 1)[1]) if uri.startswith("data:") else (path.parent / uri).read_bytes()


def base_colour_pixels(path):
    doc, buffer = gltf_document(path)
    material = doc["materials"][doc["meshes"][0]["primitives"][0]["material"]]
    assert material["pbrMetallicRoughness"]["metallicRoughnessTexture"]["index"] >= 0
    assert "specularColorTexture" in material["extensions"]["KHR_materials_specular"]
    assert "KHR_materials_specular" in doc["extensionsUsed"]
    image = doc["images"][doc["textures"][material["pbrMetallicRoughness"]["baseColorTexture"]["index"]]["source"]]
    if "uri" in image:
        return png_pixels(path=path.parent / image["uri"])
    view = doc["bufferViews"][image["bufferView"]]
    assert image["mimeType"] == "image/png"
    return png_pixels(data=buffer[view.get("byteOffset", 0):view.get("byteOffset", 0) + view["byteLength"]])


@pytest.mark.parametrize("single", [None, "m.glb", "m.gltf"])
def test_gltf_loads_in_vtk_with_its_base_colour_texture(plane, tmp_path, single):
    strokes = script(tmp_path, "s.json", PAINT)
    args = ["--gltf", str(tmp_path / single)] if single else []
    r = run("paint", str(plane), "--strokes", str(strokes), "-o", str(tmp_path / "o"), *args, "--quiet")
    assert r.returncode == 0, r.stderr
    path = tmp_path / single if single else tmp_path / "o" / "model.gltf"
    if single:  # one file: nothing beside it is needed
        shutil.rmtree(tmp_path / "o")
    reader = vtk.vtkGLTFReader()
    reader.SetFileName(str(path))
    reader.Update()
    assert reader.GetErrorCode() == 0
    assert reader.GetNumberOfTextures() == 3  # base colour, metallic-roughness, specular
    blocks = reader.GetOutput()
    it = blocks.NewIterator()
    it.InitTraversal()
    poly = it.GetCurrentDataObject()
    assert poly.GetNumberOfCells() == 2 * 64 and poly.GetPointData().GetArray("TEXCOORD_0") is not None
    # the base colour is the painted diffuse: red where painted, the default grey elsewhere
    _, pixels = base_colour_pixels(path)
    colours = {tuple(p) for p in pixels}
    assert (255, 64, 0) in colours and len(colours) >= 2, colours


def test_gltf_texture_is_the_diffuse_map(plane, tmp_path):
    strokes = script(tmp_path, "s.json", PAINT)
    r = run("paint", str(plane), "--strokes", str(strokes), "-o", str(tmp_path / "o"), "--gltf",
            str(tmp_path / "m.glb"), "--quiet")
    assert r.returncode == 0, r.stderr
    assert base_colour_pixels(tmp_path / "m.glb") == png_pixels(path=tmp_path / "o" / "diffuse.png")


def test_gltf_arguments_are_checked(plane, tmp_path):
    r = run("paint", str(plane), "--gltf", str(tmp_path / "m.fbx"))
    assert r.returncode == 2 and "--gltf must name a .glb or .gltf file" in r.stderr
    r = run("paint", str(plane), str(plane), "--strokes", str(script(tmp_path, "s.json", [])),
            "--gltf", str(tmp_path / "m.glb"))
    assert r.returncode == 2 and "--gltf keeps one surface" in r.stderr
    assert not (tmp_path / "m.glb").exists()


# ---------------------------------------------------------------- writing


def test_stale_temporaries_of_killed_runs_are_removed(plane, tmp_path):
    dead = tmp_path / ".p.tmp-999999999.meshpaint"  # above any pid_max: no such process
    alive = tmp_path / f".p.tmp-{os.getpid()}.meshpaint"  # this test's process runs
    other = tmp_path / ".notes.tmp-999999999.txt"  # not a kind of file meshpaint writes
    for f in (dead, alive, other):
        f.write_bytes(b"x" * 1000)
    r = run("paint", str(plane), "--save", str(tmp_path / "p.meshpaint"), "--quiet")
    assert r.returncode == 0, r.stderr
    assert not dead.exists() and alive.exists() and other.exists()


def test_concurrent_continuations_of_one_project_keep_every_stroke(plane, tmp_path):
    project = tmp_path / "p.meshpaint"
    assert run("paint", str(plane), "--save", str(project), "--level", "2", "--quiet").returncode == 0
    before = history_length(project)
    runs = []
    for k in range(6):
        strokes = script(tmp_path, f"s{k}.json", [{"tool": "paint", "points": [[k * 0.6 + 0.5, 2, 0]],
                                                    "radius": 0.3, "channels": {"diffuse": [1, 0, 0]}}], level=2)
        runs.append(subprocess.Popen([BIN, "paint", str(project), "--strokes", str(strokes), "--save", str(project),
                                      "--quiet"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True))
    for p in runs:
        _, err = p.communicate(timeout=600)
        assert p.returncode == 0, err
    assert history_length(project) == before + 6  # no run saved over another's stroke


# -- a full disk, for every command that writes

@pytest.fixture
def small_disk(tmp_path):
    """A 2 MiB tmpfs of its own; skips when this process may not mount one."""
    where = tmp_path / "disk"
    where.mkdir()
    r = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=2m", "tmpfs", str(where)], capture_output=True, text=True)
    if r.returncode != 0:
        pytest.skip("cannot mount a tmpfs to fill (needs root): " + (r.stderr.strip() or "mount failed"))
    yield where
    subprocess.run(["umount", "-l", str(where)], check=False)


def fill(disk):
    """Fills the disk to the last byte; returns the filler to remove."""
    filler = disk / "filler"
    fd = os.open(filler, os.O_WRONLY | os.O_CREAT | os.O_TRUNC)
    try:
        while True:
            os.write(fd, b"\0" * 4096)
    except OSError:
        pass
    finally:
        os.close(fd)
    return filler


def xvfb(*args):
    runner = shutil.which("xvfb-run")
    if not os.environ.get("DISPLAY") and not runner:
        pytest.skip("no display and no xvfb-run for --screenshot")
    return ([runner, "-a"] if not os.environ.get("DISPLAY") else []) + list(args)


CASES = {
    "subdivide_obj": (["subdivide", "{plane}", "--level", "3", "-o", "{d}/s.obj", "--quiet"], ["s.obj"]),
    "subdivide_ply": (["subdivide", "{plane}", "--level", "3", "-o", "{d}/s.ply", "--quiet"], ["s.ply"]),
    "subdivide_vtp": (["subdivide", "{plane}", "--level", "3", "-o", "{d}/s.vtp", "--quiet"], ["s.vtp"]),
    "paint_o": (["paint", "{plane}", "--strokes", "{strokes}", "-o", "{d}/out", "--quiet"],
                ["out/surface.vtp", "out/model.obj", "out/model.mtl", "out/model.gltf", "out/diffuse.png"]),
    "paint_save": (["paint", "{project}", "--strokes", "{strokes}", "--save", "{d}/p.meshpaint", "--quiet"],
                   ["p.meshpaint"]),
    "paint_gltf": (["paint", "{plane}", "--strokes", "{strokes}", "--gltf", "{d}/m.glb", "--quiet"], ["m.glb"]),
    "paint_screenshot": (["paint", "{plane}", "--strokes", "{strokes}", "--save", "{project}", "--screenshot",
                          "{d}/shot.png", "--quiet"], ["shot.png"]),
    "transfer_vtp": (["transfer", "{project}", "--to", "{plane}", "-o", "{d}/t.vtp", "--quiet"], ["t.vtp"]),
    "transfer_ply": (["transfer", "{project}", "--to", "{plane}", "-o", "{d}/t.ply", "--quiet"], ["t.ply"]),
    "fit": (["fit", "{plane}", "--direct", "--level", "2", "-o", "{d}/f.meshpaint", "--quiet"], ["f.meshpaint"]),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_a_full_disk_leaves_the_previous_file_whole(small_disk, plane, tmp_path, case):
    args, outputs = CASES[case]
    d = small_disk / "out"
    d.mkdir()
    project = tmp_path / "p.meshpaint"
    assert run("paint", str(plane), "--level", "3", "--save", str(project), "--quiet").returncode == 0
    strokes = script(tmp_path, "s.json", PAINT)
    argv = [a.format(plane=plane, d=d, strokes=strokes, project=project) for a in args]
    if case == "paint_save":
        shutil.copy(project, d / "p.meshpaint")
        argv[1] = str(d / "p.meshpaint")

    def command():
        cmd = [BIN, *argv]
        return xvfb(*cmd) if case == "paint_screenshot" else cmd

    first = subprocess.run(command(), capture_output=True, text=True, timeout=600)
    assert first.returncode == 0, first.stderr
    before = {name: (d / name).read_bytes() for name in outputs}
    filler = fill(small_disk)
    try:
        second = subprocess.run(command(), capture_output=True, text=True, timeout=600)
        listing = sorted(p.name for p in d.rglob("*"))
    finally:
        filler.unlink()
    lines = second.stderr.strip().splitlines()
    assert second.returncode == 3, second.stderr
    assert len(lines) == 1 and "No space left on device" in lines[0], second.stderr
    for name, data in before.items():
        assert (d / name).read_bytes() == data, name
    assert not [n for n in listing if ".tmp-" in n], listing
