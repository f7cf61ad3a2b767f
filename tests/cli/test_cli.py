"""The meshpaint command line: bad input, outputs, and what they contain.

Run by CTest with MESHPAINT_BIN (the executable) and MESHPAINT_SOURCE_DIR set.
"""
import json
import os
import re
import subprocess
import sys
import tempfile

import pytest
import vtk  # Debian's python3-vtk9; read our outputs with VTK itself

BIN = os.environ["MESHPAINT_BIN"]
SOURCE = os.environ["MESHPAINT_SOURCE_DIR"]
BAD = os.path.join(SOURCE, "tests", "bad_input")
SCANS = os.path.join(SOURCE, "data", "scans")

# The unit cube as quads (also read by the rendering tests).
with open(os.path.join(SOURCE, "tests", "support", "cube.obj")) as _f:
    CUBE_OBJ = _f.read()


def run(*args):
    # errors="replace": a message that is not UTF-8 shows as such, not as a test crash.
    return subprocess.run([BIN, *args], capture_output=True, text=True, errors="replace", timeout=600)


def load_cases():
    with open(os.path.join(BAD, "cases.json")) as f:
        return json.load(f)["cases"]


def generated_cases():
    """The cases of tests/bad_input/generate_cases.py, written once per run."""
    out = os.path.join(tempfile.mkdtemp(prefix="meshpaint-generated-"), "cases")
    subprocess.run([sys.executable, os.path.join(BAD, "generate_cases.py"), out, BIN], check=True, timeout=600)
    with open(os.path.join(out, "cases.json")) as f:
        return [dict(case, dir=out) for case in json.load(f)["cases"]]


def case_id(case):
    return " ".join(case["args"][:2]) + " " + os.path.basename(case["args"][-1])


def check_case(case, folder, tmp_path):
    args = [a.format(dir=folder, scans=SCANS, tmp=tmp_path) for a in case["args"]]
    r = run(*args)
    lines = r.stderr.strip().splitlines()
    if case.get("exit", 2) == 0:
        # A repair or a note: the command succeeds and says what it did.
        assert r.returncode == 0, r.stderr
        said = lines + r.stdout.splitlines()
        assert any(re.search(case["message"], line) for line in said), r.stdout + r.stderr
        assert all(line.startswith("meshpaint") or line.startswith("warning") for line in lines), r.stderr
        return
    assert r.returncode == 2, r.stderr
    assert len(lines) == 1, r.stderr
    assert re.search(case["message"], lines[0]), lines[0]
    assert lines[0].startswith("meshpaint "), lines[0]
    assert "\ufffd" not in lines[0], "the message must be valid UTF-8: " + lines[0]
    assert not (tmp_path / "out").exists(), "nothing may be written for bad input"


@pytest.mark.parametrize("case", load_cases(), ids=case_id)
def test_bad_input_gives_one_line_and_exit_2(case, tmp_path):
    check_case(case, BAD, tmp_path)


@pytest.mark.parametrize("case", generated_cases(), ids=case_id)
def test_generated_bad_input_gives_one_line_and_exit_2(case, tmp_path):
    check_case(case, case["dir"], tmp_path)


@pytest.mark.parametrize("name", ["zero-area-face", "high-valence"])
def test_awkward_meshes_give_finite_limit_surfaces(name, tmp_path):
    out = tmp_path / (name + ".obj")
    r = run("subdivide", os.path.join(BAD, name + ".obj"), "--level", "3", "--limit", "-o", str(out))
    assert r.returncode == 0, r.stderr
    text = out.read_text().lower()
    assert "nan" not in text and "inf" not in text
    poly = read_polydata(out)
    assert poly.GetNumberOfCells() > 0


def run_with_memory(cap, *args):
    env = dict(os.environ, MESHPAINT_DEVICE_MEMORY=cap)
    return subprocess.run([BIN, *args], capture_output=True, text=True, timeout=600, env=env)


def test_memory_cap_refuses_a_level_before_allocating(tmp_path):
    out = tmp_path / "x.obj"
    r = run_with_memory("84M", "subdivide", os.path.join(SCANS, "bunny00.off"), "--level", "6", "-o", str(out))
    assert r.returncode == 2, r.stderr
    assert re.fullmatch(r"meshpaint subdivide: level 6 of 'bunny00' needs .* \(84\.0 MiB\); "
                        r"the largest level that fits is 1", r.stderr.strip()), r.stderr
    assert not out.exists()
    # the level it names does fit under the same cap
    r = run_with_memory("84M", "subdivide", os.path.join(SCANS, "bunny00.off"), "--level", "1", "-o", str(out))
    assert r.returncode == 0, r.stderr
    r = run_with_memory("64M", "devices")
    assert "64.0 MiB" in r.stdout


def test_memory_cap_counts_the_paint_layers(tmp_path):
    # Level 2 of the bunny fits as an atlas under 200 MiB, not with its paint layers.
    strokes = os.path.join(SOURCE, "data", "strokes", "bunny_demo.json")
    out = tmp_path / "painted"
    r = run_with_memory("200M", "paint", os.path.join(SCANS, "bunny00.off"), "--strokes", strokes, "--level", "2",
                        "-o", str(out))
    assert r.returncode == 2, r.stderr
    assert re.fullmatch(r"meshpaint paint: painting level 2 of 'bunny00' needs .* with its paint layers, .*"
                        r"\(200\.0 MiB\); the largest level that fits for painting is 1", r.stderr.strip()), r.stderr
    assert not (out / "surface.vtp").exists()
    r = run_with_memory("200M", "paint", os.path.join(SCANS, "bunny00.off"), "--strokes", strokes, "--level", "1",
                        "--model-level", "1", "-o", str(out))
    assert r.returncode == 0, r.stderr
    assert (out / "surface.vtp").exists()


def test_memory_cap_counts_the_multiresolution_layers(tmp_path):
    # Level 2 of the bunny paints under 380 MiB (354 MiB with its paint layers), but an edit at
    # level 1 needs its details and that level's limit beside them: refused before they are
    # allocated, and nothing is written.
    stroke = {"tool": "sculpt", "points": [[-0.03, 0.12, 0.03]], "radius": 0.03, "amount": 0.002}
    coarse, fine = tmp_path / "coarse.json", tmp_path / "fine.json"
    coarse.write_text(json.dumps({"strokes": [dict(stroke, edit_level=1)]}))
    fine.write_text(json.dumps({"strokes": [stroke]}))
    out = tmp_path / "painted"
    r = run_with_memory("380M", "paint", os.path.join(SCANS, "bunny00.off"), "--strokes", str(coarse), "--level", "2",
                        "-o", str(out))
    assert r.returncode == 2, r.stderr
    assert re.fullmatch(r"meshpaint paint: editing below painting level 2 needs .* with the multiresolution layers, "
                        r"more than .* \(380\.0 MiB\); edit at the painting level, or paint at a lower one",
                        r.stderr.strip().splitlines()[-1]), r.stderr
    assert not out.exists()
    r = run_with_memory("380M", "paint", os.path.join(SCANS, "bunny00.off"), "--strokes", str(fine), "--level", "2",
                        "--model-level", "1", "-o", str(out))
    assert r.returncode == 0, r.stderr
    assert (out / "surface.vtp").exists()


def test_info_reports_what_painting_and_coarse_edits_need():
    # The levels of the test above: under 380 MiB level 2 of the bunny paints, but its
    # coarse edits are over; with no cap both fit.
    def level_row(cap, level):
        r = run_with_memory(cap, "info", os.path.join(SCANS, "bunny00.off"))
        assert r.returncode == 0, r.stderr
        header = next(l for l in r.stdout.splitlines() if l.lstrip().startswith("level"))
        assert re.search(r"atlas 1\.\.L\s+painting\s+coarse edits\s+fits$", header), header
        row = next(l for l in r.stdout.splitlines() if re.match(r"\s*%d\s" % level, l))
        return row

    capped = level_row("380M", 2)
    painting, coarse = re.search(r"(\S+ [KMG]?i?B)\s+(\S+ [KMG]?i?B \(over\))\s+yes$", capped).groups()
    assert "(over)" not in painting
    assert "(over)" not in level_row("4G", 2)
    assert re.search(r"\s-\s+yes$", level_row("4G", 1))  # nothing below level 1 to edit


def test_memory_cap_must_be_a_size(tmp_path):
    r = run_with_memory("lots", "subdivide", os.path.join(SCANS, "bunny00.off"), "--level", "2",
                        "-o", str(tmp_path / "x.obj"))
    assert r.returncode == 2
    assert r.stderr.strip() == "meshpaint subdivide: MESHPAINT_DEVICE_MEMORY must be a size such as 512M or 2G, not 'lots'"


def test_unknown_device_is_a_device_error(tmp_path):
    r = run("info", os.path.join(SCANS, "bunny00.off"), "--device", "no-such-device")
    # info still reports the mesh and says there is no such device
    assert r.returncode == 0
    assert "no OpenCL device matches 'no-such-device'" in r.stdout
    r = run("subdivide", os.path.join(SCANS, "bunny00.off"), "--level", "2", "--device", "no-such-device",
            "-o", str(tmp_path / "x.obj"))
    assert r.returncode == 3
    assert len(r.stderr.strip().splitlines()) == 1
    assert not (tmp_path / "x.obj").exists()


@pytest.fixture
def cube(tmp_path):
    path = tmp_path / "cube.obj"
    path.write_text(CUBE_OBJ)
    return path


def read_polydata(path):
    reader = {".vtp": vtk.vtkXMLPolyDataReader, ".ply": vtk.vtkPLYReader, ".obj": vtk.vtkOBJReader}[path.suffix]()
    reader.SetFileName(str(path))
    reader.Update()
    return reader.GetOutput()


@pytest.mark.parametrize("ext", [".obj", ".ply", ".vtp"])
def test_subdivide_writes_welded_quads(cube, tmp_path, ext):
    out = tmp_path / ("cube2" + ext)
    r = run("subdivide", str(cube), "--level", "2", "-o", str(out), "--quiet")
    assert r.returncode == 0, r.stderr
    poly = read_polydata(out)
    # OpenSubdiv's counts for a cube at level 2: 98 vertices, 96 quads.
    assert poly.GetNumberOfPoints() == 98
    assert poly.GetNumberOfCells() == 96
    assert all(poly.GetCell(i).GetNumberOfPoints() == 4 for i in range(poly.GetNumberOfCells()))


def test_subdivide_limit_writes_unit_normals(cube, tmp_path):
    out = tmp_path / "cube3.vtp"
    r = run("subdivide", str(cube), "--level", "3", "--limit", "-o", str(out))
    assert r.returncode == 0, r.stderr
    poly = read_polydata(out)
    normals = poly.GetPointData().GetArray("Normals")
    assert normals is not None and normals.GetNumberOfComponents() == 3
    assert poly.GetNumberOfPoints() == 386
    center = (0.5, 0.5, 0.5)
    for i in range(poly.GetNumberOfPoints()):
        n = normals.GetTuple3(i)
        p = poly.GetPoint(i)
        assert abs(sum(c * c for c in n) - 1.0) < 1e-5
        # a convex closed surface: normals point away from the centre
        assert sum(n[k] * (p[k] - center[k]) for k in range(3)) > 0


def test_failed_subdivide_leaves_existing_output_untouched(cube, tmp_path):
    out = tmp_path / "keep.obj"
    out.write_text("precious\n")
    r = run("subdivide", str(cube), "--level", "13", "-o", str(out))
    assert r.returncode == 2
    assert out.read_text() == "precious\n"
    assert [p.name for p in tmp_path.iterdir()] == sorted(["cube.obj", "keep.obj"]) or \
        sorted(p.name for p in tmp_path.iterdir()) == ["cube.obj", "keep.obj"]


def test_info_reports_topology(tmp_path):
    # An open box (cube without its top): one boundary loop, genus 0.
    lines = CUBE_OBJ.strip().splitlines()
    path = tmp_path / "box.obj"
    path.write_text("\n".join(l for l in lines if l != "f 5 6 7 8") + "\n")
    r = run("info", str(path))
    assert r.returncode == 0, r.stderr
    assert "8 vertices, 12 edges, 5 faces (5 quads)" in r.stdout
    assert "1 component, genus 0" in r.stdout
    assert "boundaries   1 loop, 4 edges" in r.stdout
    assert re.search(r"^\s+3\s+5x5\s", r.stdout, re.M)


def test_info_reports_repairs(tmp_path):
    # Three faces on one edge, and a face naming a vertex twice.
    path = tmp_path / "fin.obj"
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 2 2 2\n"
                    "f 1 2 3\nf 2 1 4\nf 1 2 5\nf 1 3 3\n")
    r = run("info", str(path))
    assert r.returncode == 0, r.stderr
    assert re.search(r"dropped 1 (degenerate face|face the file lists but the reader could not use)", r.stderr)
    # The edge with three faces cannot be oriented: the faces are cut apart there.
    assert re.search(r"imported: cut [0-9]+ non-orientable or non-manifold components? open at [0-9]+ vertex cop(y|ies)",
                     r.stderr)
    assert re.search(r"removed (1 vertex|2 vertices) used by no face", r.stderr)


def test_bench_json_line(tmp_path, cube):
    r = run("bench", "subdivide", str(cube), "--level", "3", "--json", "--repeats", "3")
    assert r.returncode == 0, r.stderr
    result = json.loads(r.stdout.strip().splitlines()[-1])
    for key in ("engine_ms", "opensubdiv_ms", "vertices", "ratio", "max_deviation"):
        assert key in result
    assert result["vertices"] == 386
    assert result["max_deviation"] <= 1e-5
    assert_host_memory(result)
    assert_copy_probe(result)
    # a CPU's first two steps walk their sides in the tile kernel (no side
    # kernel below level 3), a GPU runs a side kernel every step
    families = result["kernel_families"]
    edges = {"subdivide edges"} if "subdivide edges" in [f["family"] for f in families] else set()
    assert_families(families, {"subdivide corners", "subdivide tiles"} | edges)
    assert [(s["from"], s["to"]) for s in result["level_steps"]] == [(1, 2), (2, 3)]
    assert all(s["ms"] > 0 and s["gb_per_s"] > 0 for s in result["level_steps"]), result["level_steps"]


def assert_copy_probe(result):
    # the device's copy bandwidth, the ceiling the family columns are read against
    probe = result["device_copy_gb_per_s"]
    assert set(probe) == {"enqueue_copy", "copy_kernel", "mib"}
    assert probe["mib"] > 0 and probe["enqueue_copy"] > 0 and probe["copy_kernel"] > 0, probe


def assert_families(families, expected):
    # every family that ran, then "all": their times add up, and each moved bytes
    names = [f["family"] for f in families]
    assert names[-1] == "all" and set(names[:-1]) == expected, names
    assert all(f["ms"] > 0 and f["gb_per_s"] > 0 for f in families), families
    assert abs(sum(f["ms"] for f in families[:-1]) - families[-1]["ms"]) <= 1e-3 * families[-1]["ms"] + 1e-6


def assert_host_memory(result):
    # the host's dependent-read probe rides with every bench's figures
    probe = result["host_memory_ns"]
    assert set(probe) == {"2MiB", "64MiB"}
    assert all(0 < ns < 1e6 for ns in probe.values()), probe


def test_bench_paint_phases_account_for_the_step():
    r = run("bench", "paint", "--mesh", "femur", "--steps", "1", "--phases", "--json")
    assert r.returncode == 0, r.stderr
    result = json.loads(r.stdout.strip().splitlines()[-1])
    assert_host_memory(result)
    assert_copy_probe(result)
    assert [m["mesh"] for m in result["limit_families"]] == ["femur L2"]
    # buffer storage on a CPU device makes the bounds inside limit_patches; elsewhere a kernel of their own
    families = result["limit_families"][0]["families"]
    base = {"limit edges", "limit corners", "limit tiles"}
    assert_families(families, base | ({"patch bounds"} if "patch bounds" in [f["family"] for f in families] else set()))
    rows = {row["step"]: row for row in result["phases"]}
    assert set(rows) == {"sculpt 50%", "coarse sculpt 50%"}
    names = ("place", "record", "weights", "transform", "rebuild", "lists", "limit")
    for step, row in rows.items():
        parts = [row[name + "_ms"] for name in names]
        assert all(p >= 0 for p in parts), row
        # the phases split the step's wall time: together they cannot exceed it
        assert sum(parts) <= row["whole_ms"], row
        for ran in ("place", "transform", "lists", "limit"):
            assert row[ran + "_ms"] > 0, (step, ran)
    # a coarse edit weighs on its own; a sculpt at the painting level as it moves
    assert rows["coarse sculpt 50%"]["weights_ms"] > 0
    # only a coarse edit rebuilds the finest level
    assert rows["sculpt 50%"]["rebuild_ms"] == 0
    assert rows["coarse sculpt 50%"]["rebuild_ms"] > 0


def test_demo_writes_its_surface(tmp_path):
    r = run("demo", "--level", "2", "-o", str(tmp_path / "demo"))
    assert r.returncode == 0, r.stderr
    out = tmp_path / "demo" / "bunny00_level2_limit.vtp"
    assert out.exists()
    assert read_polydata(out).GetNumberOfPoints() == 904898
    painted = read_polydata(tmp_path / "demo" / "painted" / "surface.vtp")
    labels = painted.GetPointData().GetArray("label")
    assert any(labels.GetValue(i) == 1 for i in range(labels.GetNumberOfTuples()))
    assert (tmp_path / "demo" / "painted" / "model.obj").exists()


def test_devices_lists_the_default(tmp_path):
    r = run("devices")
    assert r.returncode == 0, r.stderr
    assert "*" in r.stdout


def test_no_opencl_platform_says_how_to_install_pocl(cube, tmp_path):
    env = dict(os.environ, OCL_ICD_VENDORS=str(tmp_path / "no-vendors"))
    r = subprocess.run([BIN, "subdivide", str(cube), "--level", "2", "-o", str(tmp_path / "x.obj")],
                       capture_output=True, text=True, env=env, timeout=60)
    assert r.returncode == 3
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1, r.stderr
    assert "no OpenCL platform found: install PoCL" in lines[0]


PLANE_OBJ = "".join(f"v {x} {y} 0\n" for y in range(5) for x in range(5)) + "".join(
    f"f {y * 5 + x + 1} {y * 5 + x + 2} {(y + 1) * 5 + x + 2} {(y + 1) * 5 + x + 1}\n" for y in range(4) for x in range(4))


@pytest.fixture
def plane(tmp_path):
    path = tmp_path / "plane.obj"
    path.write_text(PLANE_OBJ)
    return path


def test_paint_writes_channels(plane, tmp_path):
    script = tmp_path / "s.json"
    script.write_text(json.dumps({"level": 3, "strokes": [
        {"tool": "paint", "points": [[1, 1, 0], [3, 1, 0]], "radius": 0.5, "falloff": "constant",
         "channels": {"diffuse": [1, 0, 0], "roughness": 0.25}},
        {"tool": "label", "points": [[2, 3, 0]], "radius": 0.6, "channels": {"label": 4}}]}))
    r = run("paint", str(plane), "--strokes", str(script), "-o", str(tmp_path / "out"), "--quiet")
    assert r.returncode == 0, r.stderr
    assert "stroke" in r.stdout
    poly = read_polydata(tmp_path / "out" / "surface.vtp")
    pd = poly.GetPointData()
    for name, comps in (("diffuse", 3), ("specular", 3), ("roughness", 1), ("displacement", 1), ("label", 1),
                        ("Normals", 3)):
        assert pd.GetArray(name) is not None and pd.GetArray(name).GetNumberOfComponents() == comps, name
    red = labelled = 0
    for i in range(poly.GetNumberOfPoints()):
        x, y, _ = poly.GetPoint(i)
        d = pd.GetArray("diffuse").GetTuple3(i)
        if d == (1.0, 0.0, 0.0):
            red += 1
            assert pd.GetArray("roughness").GetValue(i) == 0.25
        if pd.GetArray("label").GetValue(i) == 4:
            labelled += 1
            assert (x - 2) ** 2 + (y - 3) ** 2 <= 0.6 ** 2 + 1e-6
    assert red > 10 and labelled > 5


def test_paint_coarse_edit_level_and_lod(plane, tmp_path):
    script = tmp_path / "s.json"
    script.write_text(json.dumps({"level": 4, "strokes": [
        {"tool": "grab", "points": [[2, 2, 0], [2, 2, 0.4]], "radius": 1.2, "edit_level": 2},
        {"tool": "sculpt", "points": [[2, 2, 0.4]], "radius": 0.6, "amount": 0.05},
        {"tool": "grab", "points": [[1, 1, 0], [1, 1, 6]], "radius": 0.5, "edit_level": 1}]}))
    out = tmp_path / "out"
    r = run("paint", str(plane), "--strokes", str(script), "--lod", "2", "-o", str(out), "--quiet")
    assert r.returncode == 0, r.stderr
    assert re.search(r"warning: stroke 2: edit level 1 undersamples the surface", r.stderr), r.stderr
    assert "stretched" in r.stdout
    full, lod = read_polydata(out / "surface.vtp"), read_polydata(out / "surface_lod2.vtp")
    assert 0 < lod.GetNumberOfPoints() < full.GetNumberOfPoints()
    assert lod.GetPointData().GetArray("Normals") is not None
    top = max(full.GetPoint(i)[2] for i in range(full.GetNumberOfPoints()))
    assert top > 0.3


def test_paint_a_scene_of_two_objects(plane, tmp_path):
    # A second plate beside the first, touching it along x = 4.
    right = tmp_path / "right.obj"
    right.write_text("".join(f"v {x + 4} {y} 0\n" for y in range(5) for x in range(5)) + PLANE_OBJ.split("\n", 25)[25])
    script = tmp_path / "s.json"
    script.write_text(json.dumps({"level": 3, "strokes": [
        {"tool": "paint", "points": [[2, 2, 0], [6, 2, 0]], "radius": 0.5, "falloff": "constant", "space": "tangent",
         "channels": {"diffuse": [1, 0, 0]}},
        {"tool": "paint", "points": [[4.2, 3.05, 0]], "radius": 0.3, "space": "parameter", "falloff": "constant",
         "channels": {"diffuse": [0, 0, 1]}}]}))
    out = tmp_path / "out"
    r = run("paint", str(plane), str(right), "--strokes", str(script), "-o", str(out), "--quiet", "--two-sided")
    assert r.returncode == 0, r.stderr
    counts = {}
    for name in ("plane", "right"):
        poly = read_polydata(out / name / "surface.vtp")
        d = poly.GetPointData().GetArray("diffuse")
        assert poly.GetPointData().GetArray("inside_diffuse") is not None
        assert (out / name / "inside_diffuse.png").exists()
        counts[name] = (sum(d.GetTuple3(i) == (1.0, 0.0, 0.0) for i in range(poly.GetNumberOfPoints())),
                        sum(d.GetTuple3(i) == (0.0, 0.0, 1.0) for i in range(poly.GetNumberOfPoints())))
    assert counts["plane"][0] > 10 and counts["right"][0] > 10  # the stroke crosses the contact
    assert counts["plane"][1] == 0 and counts["right"][1] > 0   # a parameter-space dab paints one object
    r = run("paint", str(plane), str(right), "--strokes", str(script), "--save", str(tmp_path / "p.meshpaint"))
    assert r.returncode == 2 and "--save keeps one surface" in r.stderr


def test_paint_refuses_an_edit_level_finer_than_the_painting_level(plane, tmp_path):
    script = tmp_path / "s.json"
    script.write_text(json.dumps({"strokes": [
        {"tool": "sculpt", "points": [[2, 2, 0]], "radius": 1, "amount": 0.1, "edit_level": 4}]}))
    out = tmp_path / "out"
    r = run("paint", str(plane), "--strokes", str(script), "--level", "3", "-o", str(out))
    assert r.returncode == 2 and not out.exists()
    assert r.stderr.strip() == 'meshpaint paint: stroke 0: "edit_level" 4 is finer than the painting level 3', r.stderr


@pytest.mark.parametrize("stroke,message", [
    ({"tool": "paint", "points": [[1, 1, 0]], "radius": 0, "channels": {"diffuse": [1, 0, 0]}},
     r"stroke 1: \"radius\" must be a number"),
    ({"tool": "smudge", "points": [[1, 1, 0]], "radius": 1}, r"stroke 1: \"tool\" must be one of"),
    ({"tool": "paint", "points": [[1, 1, 0]], "radius": 1, "channels": {"diffuse": [1, 0, 0]}, "size": 3},
     r"stroke 1: \"size\" is not a stroke key"),
    ({"tool": "paint", "points": [], "radius": 1, "channels": {"diffuse": [1, 0, 0]}},
     r"stroke 1: \"points\" is empty"),
    ({"tool": "paint", "points": [[1, 1, 0]], "radius": 1, "strength": float("nan"), "channels": {"diffuse": [1, 0, 0]}},
     r"not valid JSON|\"strength\" must be a number"),
])
def test_bad_stroke_scripts_name_stroke_and_key(plane, tmp_path, stroke, message):
    good = {"tool": "paint", "points": [[1, 1, 0]], "radius": 0.5, "channels": {"diffuse": [0, 1, 0]}}
    script = tmp_path / "bad.json"
    script.write_text(json.dumps({"strokes": [good, stroke]}))
    out = tmp_path / "out"
    r = run("paint", str(plane), "--strokes", str(script), "-o", str(out))
    assert r.returncode == 2, r.stderr
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and re.search(message, lines[0]), r.stderr
    assert not out.exists(), "nothing may be written when the script is bad"


def test_paint_model_textures_match_the_surface(plane, tmp_path):
    import numpy as np
    from vtkmodules.util.numpy_support import vtk_to_numpy

    script = tmp_path / "s.json"
    script.write_text(json.dumps({"strokes": [
        {"tool": "paint", "points": [[1.2, 1.3, 0], [2.7, 2.9, 0]], "radius": 0.7, "falloff": "linear",
         "channels": {"diffuse": [0.1, 0.9, 0.3], "roughness": 1.0}}]}))
    out = tmp_path / "out"
    r = run("paint", str(plane), "--strokes", str(script), "--level", "4", "--model-level", "3", "-o", str(out))
    assert r.returncode == 0, r.stderr
    for name in ("model.obj", "model.mtl", "diffuse.png", "specular.png", "roughness.png", "displacement.png"):
        assert (out / name).exists(), name
    assert "map_Kd diffuse.png" in (out / "model.mtl").read_text()

    surface = read_polydata(out / "surface.vtp")
    s_points = vtk_to_numpy(surface.GetPoints().GetData())
    s_diffuse = vtk_to_numpy(surface.GetPointData().GetArray("diffuse"))
    lookup = {tuple(np.round(p, 5)): d for p, d in zip(s_points, s_diffuse)}

    reader = vtk.vtkPNGReader()
    reader.SetFileName(str(out / "diffuse.png"))
    reader.Update()
    img = reader.GetOutput()
    w, h, _ = img.GetDimensions()
    pixels = vtk_to_numpy(img.GetPointData().GetScalars()).reshape(h, w, -1)  # row 0 = bottom

    # Every face corner's texture coordinate lands on the pixel that holds
    # the colour of that corner on the painted surface.
    lines = (out / "model.obj").read_text().splitlines()
    v = [tuple(map(float, l.split()[1:4])) for l in lines if l.startswith("v ")]
    vt = [tuple(map(float, l.split()[1:3])) for l in lines if l.startswith("vt ")]
    checked = 0
    for l in lines:
        if not l.startswith("f "):
            continue
        for corner in l.split()[1:]:
            vi, ti, _ = (int(x) - 1 for x in corner.split("/"))
            u, vv = vt[ti]
            px, py = int(u * w), int(vv * h)  # v up: VTK's row 0 is the bottom too
            expected = lookup[tuple(np.round(v[vi], 5))]
            assert np.all(np.abs(pixels[py, px, :3] / 255.0 - expected) <= 0.5 / 255 + 1e-6), (v[vi], expected)
            checked += 1
    assert checked == 4 * (16 * 4) * (4 * 4)  # corners x patches (4 per base quad) x 4x4 cells at level 3


def write_png(path, pixels):
    """pixels: rows (top first) of grey values 0..255."""
    img = vtk.vtkImageData()
    h, w = len(pixels), len(pixels[0])
    img.SetDimensions(w, h, 1)
    img.AllocateScalars(vtk.VTK_UNSIGNED_CHAR, 1)
    for y in range(h):
        for x in range(w):
            img.SetScalarComponentFromDouble(x, h - 1 - y, 0, 0, pixels[y][x])
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(str(path))
    writer.SetInputData(img)
    writer.Write()


def test_paint_with_image_pattern_and_stamp_files(plane, tmp_path):
    write_png(tmp_path / "checker.png", [[0, 255], [255, 0]])
    write_png(tmp_path / "stamp.png", [[255, 255], [255, 255]])
    script = tmp_path / "s.json"
    script.write_text(json.dumps({"strokes": [
        {"tool": "wash", "channels": {"diffuse": [1, 0, 0]},
         "pattern": {"type": "image", "coord": "uv", "file": "checker.png"}},
        {"tool": "paint", "points": [[2, 2, 0]], "radius": 0.5, "stamp": "stamp.png",
         "channels": {"roughness": 1.0}}]}))
    r = run("paint", str(plane), "--strokes", str(script), "-o", str(tmp_path / "out"), "--quiet")
    assert r.returncode == 0, r.stderr
    poly = read_polydata(tmp_path / "out" / "surface.vtp")
    greens = {round(poly.GetPointData().GetArray("diffuse").GetTuple3(i)[1], 3) for i in range(poly.GetNumberOfPoints())}
    assert len(greens) > 2, "a checker pattern gives several shades"
    rough = [poly.GetPointData().GetArray("roughness").GetValue(i) for i in range(poly.GetNumberOfPoints())]
    assert max(rough) == 1.0


def test_paint_with_a_missing_pattern_file_names_the_stroke(plane, tmp_path):
    script = tmp_path / "s.json"
    script.write_text(json.dumps({"strokes": [
        {"tool": "wash", "channels": {"diffuse": [1, 0, 0]}},
        {"tool": "wash", "channels": {"diffuse": [1, 0, 0]}, "pattern": {"type": "image", "file": "gone.png"}}]}))
    r = run("paint", str(plane), "--strokes", str(script), "-o", str(tmp_path / "out"))
    assert r.returncode == 2
    assert re.search(r"stroke 1: cannot open '.*gone.png': no such file", r.stderr), r.stderr
    assert not (tmp_path / "out").exists()
