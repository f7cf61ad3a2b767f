"""Projects on the command line: saving, continuing, statistics per label, and
refusing damaged files. Run by CTest like test_cli.py."""
import json
import os
import random
import re
import signal
import struct
import subprocess
import time

import pytest

from test_cli import BIN, PLANE_OBJ, SCANS, read_polydata, run


@pytest.fixture
def plane(tmp_path):
    path = tmp_path / "plane.obj"
    path.write_text(PLANE_OBJ)
    return path


def script(tmp_path, name, strokes, level=None):
    path = tmp_path / name
    body = {"strokes": strokes}
    if level is not None:
        body["level"] = level
    path.write_text(json.dumps(body))
    return path


RED = {"tool": "paint", "points": [[1, 1, 0], [3, 1, 0]], "radius": 0.5, "falloff": "constant",
       "channels": {"diffuse": [1, 0, 0]}}
LABEL = {"tool": "label", "points": [[2, 3, 0]], "radius": 0.6, "falloff": "constant", "channels": {"label": 4}}
SCULPT = {"tool": "sculpt", "points": [[2, 2, 0]], "radius": 0.8, "amount": 0.1}


def point_arrays(path):
    poly = read_polydata(path)
    pd = poly.GetPointData()
    points = [poly.GetPoint(i) for i in range(poly.GetNumberOfPoints())]
    arrays = {pd.GetArrayName(k): [pd.GetArray(k).GetTuple(i) for i in range(poly.GetNumberOfPoints())]
              for k in range(pd.GetNumberOfArrays())}
    return points, arrays


def info_lines(path):
    r = run("info", str(path))
    assert r.returncode == 0, r.stderr
    return r.stdout


def history_length(path):
    out = info_lines(path)
    counts = [int(line.split()[1]) for line in out.splitlines() if line.startswith("history ")]
    assert len(counts) == 1, out
    return counts[0]


def test_continuing_a_project_paints_what_one_run_paints(plane, tmp_path):
    first = script(tmp_path, "a.json", [RED, SCULPT], level=3)
    second = script(tmp_path, "b.json", [LABEL])
    both = script(tmp_path, "ab.json", [RED, SCULPT, LABEL], level=3)
    project = tmp_path / "p.meshpaint"
    r = run("paint", str(plane), "--strokes", str(first), "--save", str(project), "--quiet")
    assert r.returncode == 0, r.stderr
    assert f"saved      {project}" in r.stdout
    r = run("paint", str(project), "--strokes", str(second), "-o", str(tmp_path / "continued"),
            "--save", str(tmp_path / "q.meshpaint"), "--quiet")
    assert r.returncode == 0, r.stderr
    r = run("paint", str(plane), "--strokes", str(both), "-o", str(tmp_path / "once"), "--quiet")
    assert r.returncode == 0, r.stderr
    continued = point_arrays(tmp_path / "continued" / "surface.vtp")
    once = point_arrays(tmp_path / "once" / "surface.vtp")
    assert continued[0] == once[0]
    assert continued[1] == once[1]
    # the history grows with every run
    assert history_length(project) == 2
    assert history_length(tmp_path / "q.meshpaint") == 3


# Label edits with the guards: a band of class 2, a fill on either side,
# class 4 painted with 2 locked, then only over unlabelled surface, a merge.
LABEL_EDITS = [
    {"tool": "label", "points": [[2, 0, 0], [2, 4, 0]], "radius": 0.4, "falloff": "constant", "channels": {"label": 2}},
    {"tool": "fill", "points": [[1, 2, 0]], "radius": 0.3, "channels": {"label": 3}},
    {"tool": "label", "points": [[1.5, 1, 0], [2.5, 1, 0]], "radius": 0.6, "channels": {"label": 4},
     "locked_labels": [2]},
    {"tool": "label", "points": [[2.6, 3, 0]], "radius": 0.9, "channels": {"label": 5}, "only_over_label": 0},
    {"tool": "merge", "only_over_label": 3, "channels": {"label": 6}, "locked_labels": [4]},
]


def test_label_edits_replay_to_the_same_bits(plane, tmp_path):
    # Once whole, and continued stroke by stroke from the saved project
    # (whose history holds the new keys and tools): the same bits.
    whole = script(tmp_path, "whole.json", LABEL_EDITS, level=3)
    r = run("paint", str(plane), "--strokes", str(whole), "-o", str(tmp_path / "once"), "--quiet")
    assert r.returncode == 0, r.stderr
    project = tmp_path / "p.meshpaint"
    first = script(tmp_path, "s0.json", LABEL_EDITS[:1], level=3)
    r = run("paint", str(plane), "--strokes", str(first), "--save", str(project), "--quiet")
    assert r.returncode == 0, r.stderr
    for k, stroke in enumerate(LABEL_EDITS[1:], 1):
        r = run("paint", str(project), "--strokes", str(script(tmp_path, f"s{k}.json", [stroke])),
                "--save", str(project), "-o", str(tmp_path / "continued"), "--quiet")
        assert r.returncode == 0, r.stderr
    assert history_length(project) == len(LABEL_EDITS)
    once = point_arrays(tmp_path / "once" / "surface.vtp")
    continued = point_arrays(tmp_path / "continued" / "surface.vtp")
    assert once[0] == continued[0]
    assert once[1] == continued[1]
    labels = {int(v[0]) for v in once[1]["label"]}
    # 3 was filled in and merged into 6; 4 and 5 painted; 2 kept its band.
    assert labels >= {2, 4, 5, 6} and 3 not in labels, labels


def test_subdivide_and_stats_take_a_project(plane, tmp_path):
    strokes = script(tmp_path, "s.json", [SCULPT, LABEL], level=3)
    project = tmp_path / "p.meshpaint"
    labels = tmp_path / "labels.json"
    labels.write_text(json.dumps([{"id": 4, "name": "spot", "colour": [1, 0, 0]},
                                  {"id": 9, "name": "unused", "colour": [0, 0, 1]}]))
    r = run("paint", str(plane), "--strokes", str(strokes), "--save", str(project), "--labels", str(labels),
            "-o", str(tmp_path / "out"), "--quiet")
    assert r.returncode == 0, r.stderr
    # the project's limit surface is the painted one (no displacement painted)
    r = run("subdivide", str(project), "--level", "3", "--limit", "-o", str(tmp_path / "limit.vtp"), "--quiet")
    assert r.returncode == 0, r.stderr
    assert point_arrays(tmp_path / "limit.vtp")[0] == point_arrays(tmp_path / "out" / "surface.vtp")[0]
    r = run("subdivide", str(project), "--level", "4", "-o", str(tmp_path / "finer.obj"), "--quiet")
    assert r.returncode == 0, r.stderr
    assert max(p[2] for p in point_arrays(tmp_path / "finer.obj")[0]) > 0.05  # the sculpted bump stays

    r = run("stats", str(project), "--json")
    assert r.returncode == 0, r.stderr
    stats = json.loads(r.stdout)
    by_id = {l["id"]: l for l in stats["labels"]}
    assert by_id[4]["name"] == "spot" and by_id[4]["colour"] == [1, 0, 0]
    assert by_id[9]["area"] == 0 and by_id[9]["centroid"] is None
    assert by_id[0]["name"] == "unlabelled"
    assert sum(l["area"] for l in stats["labels"]) == pytest.approx(stats["area"], rel=1e-9)
    spot = by_id[4]
    # a disc of radius 0.6 around (2, 3), flat there: area near pi r^2, centred
    assert spot["area"] == pytest.approx(3.14159 * 0.36, rel=0.15)
    assert spot["centroid"][0] == pytest.approx(2, abs=0.05) and spot["centroid"][1] == pytest.approx(3, abs=0.05)
    assert 1.4 <= spot["bbox_min"][0] <= 1.6 and 2.4 <= spot["bbox_max"][0] <= 2.6

    r = run("stats", str(project), "--csv")
    assert r.returncode == 0, r.stderr
    rows = r.stdout.strip().splitlines()
    assert rows[0].startswith("id,name,vertices,area,area_fraction,centroid_x")
    assert any(row.startswith('4,"spot",') for row in rows)
    r = run("stats", str(project))
    assert r.returncode == 0, r.stderr
    assert "spot" in r.stdout and "unlabelled" in r.stdout


def damaged(tmp_path, plane, change):
    project = tmp_path / "p.meshpaint"
    r = run("paint", str(plane), "--save", str(project), "--quiet")
    assert r.returncode == 0, r.stderr
    data = bytearray(project.read_bytes())
    bad = tmp_path / "bad.meshpaint"
    bad.write_bytes(change(data))
    return bad


@pytest.mark.parametrize("change, message", [
    (lambda d: d[:len(d) - 10], r"truncated project \(\d+ bytes, the header promises \d+\)"),
    (lambda d: d[:20], r"truncated project \(the header ends early\)"),
    (lambda d: d[:60] + bytes([d[60] ^ 1]) + d[61:], r"corrupt project \(payload checksum mismatch\)"),
    (lambda d: d[:20] + bytes([d[20] ^ 1]) + d[21:], r"corrupt project \(header checksum mismatch\)"),
    (lambda d: d[:8] + struct.pack("<I", 7) + d[12:],
     r"project format version 7 is newer than this meshpaint reads \(up to 1\); open it with a newer meshpaint"),
    (lambda d: b"solid cube\n" + d, r"not a meshpaint project"),
])
@pytest.mark.parametrize("command", ["info", "paint", "subdivide", "stats"])
def test_damaged_projects_give_one_line_and_exit_2(plane, tmp_path, change, message, command):
    bad = damaged(tmp_path, plane, change)
    args = {"info": [], "stats": [], "paint": ["--save", str(tmp_path / "out.meshpaint")],
            "subdivide": ["--level", "2", "-o", str(tmp_path / "x.obj")]}[command]
    r = run(command, str(bad), *args)
    lines = r.stderr.strip().splitlines()
    assert r.returncode == 2, r.stderr
    assert len(lines) == 1, r.stderr
    assert lines[0].startswith(f"meshpaint {command}: {bad}: ")
    assert re.search(message, lines[0]), lines[0]
    assert not (tmp_path / "out.meshpaint").exists() and not (tmp_path / "x.obj").exists()


@pytest.mark.parametrize("args, message", [
    (["--level", "4", "--save", "{tmp}/y.meshpaint"], r"is a level-3 project; --level 4 cannot change that"),
    (["--save", "{tmp}/x.vtp"], r"--save needs a file name ending in .meshpaint, not '.*x.vtp'"),
    ([], r"-o OUTDIR, --gltf FILE or --save P.meshpaint is required"),
    (["--save", "{tmp}/y.meshpaint", "--labels", "{tmp}/labels.json"], r"labels.json: label 0: \"colour\" must be \[r, g, b\]"),
])
def test_project_arguments_are_checked(plane, tmp_path, args, message):
    project = tmp_path / "p.meshpaint"
    assert run("paint", str(plane), "--save", str(project), "--level", "3").returncode == 0
    (tmp_path / "labels.json").write_text(json.dumps([{"id": 1, "name": "a", "colour": [1, 0]}]))
    r = run("paint", str(project), *[a.format(tmp=tmp_path) for a in args])
    lines = r.stderr.strip().splitlines()
    assert r.returncode == 2 and len(lines) == 1, r.stderr
    assert re.search(message, lines[0]), lines[0]


def test_killed_while_saving_the_previous_project_still_loads(tmp_path):
    """Kills `meshpaint paint P --save P` with a signal at random moments:
    half of the runs at a random time while they work, half just after their
    temporary file appears (during the write itself). P must always load,
    with its history from before or after that run, never anything between."""
    mesh = os.path.join(SCANS, "femur.off")
    if not os.path.exists(mesh):
        pytest.skip("data/scans/femur.off missing (scripts/fetch-scans.sh)")
    project = tmp_path / "femur.meshpaint"
    strokes = script(tmp_path, "s.json", [{"tool": "wash", "channels": {"diffuse": [0.5, 0.6, 0.7]},
                                           "strength": 0.5}])
    r = run("paint", mesh, "--level", "3", "--save", str(project), "--quiet")
    assert r.returncode == 0, r.stderr
    # How long one run takes, to spread the kills over it.
    started = time.monotonic()
    r = run("paint", str(project), "--strokes", str(strokes), "--save", str(project), "--quiet")
    assert r.returncode == 0, r.stderr
    duration = time.monotonic() - started
    history = 1
    rng = random.Random(7)
    killed = caught_writing = 0
    for attempt in range(12):
        p = subprocess.Popen([BIN, "paint", str(project), "--strokes", str(strokes), "--save", str(project),
                              "--quiet"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        temporary = tmp_path / f".femur.tmp-{p.pid}.meshpaint"
        if attempt % 2:
            deadline = time.monotonic() + 3 * duration + 5
            while not temporary.exists() and p.poll() is None and time.monotonic() < deadline:
                time.sleep(0.0005)
            time.sleep(rng.uniform(0, 0.002))
        else:
            time.sleep(rng.uniform(0.2, 1.0) * duration)
        sig = rng.choice([signal.SIGKILL, signal.SIGTERM, signal.SIGINT])
        writing = temporary.exists()
        p.send_signal(sig)
        code = p.wait(timeout=120)
        killed += code != 0
        caught_writing += writing and code != 0  # died in the middle of writing it
        if sig != signal.SIGKILL:  # a signal it can catch: it removed its temporary
            assert not temporary.exists(), (attempt, sig)

        now = history_length(project)
        assert now in (history, history + 1), (attempt, now, history)
        history = now
    assert killed >= 6, "too few runs were killed while working to test anything"
    assert caught_writing >= 1, "no run was killed while writing its file"
    # Temporaries of runs killed by SIGKILL go with the next save into the folder.
    assert run("paint", str(project), "--save", str(project), "--quiet").returncode == 0
    assert list(tmp_path.glob(".femur.tmp-*")) == [], "a later save leaves the temporary of a killed run behind"

def off_points(path):
    lines = [l for l in open(path).read().split("\n") if l.strip() and not l.startswith("#")]
    nv = int(lines[1].split()[0])
    return [tuple(float(x) for x in l.split()[:3]) for l in lines[2:2 + nv]]


def dist(a, b):
    return sum((x - y) ** 2 for x, y in zip(a, b)) ** 0.5


@pytest.fixture(scope="module")
def bunny_transfer(tmp_path_factory):
    """The bunny used as its own base mesh (level 2), a label dab of radius r
    and a sculpt dab at scan vertex 1000, handed back to the scan."""
    mesh = os.path.join(SCANS, "bunny00.off")
    if not os.path.exists(mesh):
        pytest.skip("data/scans/bunny00.off missing (scripts/fetch-scans.sh)")
    tmp = tmp_path_factory.mktemp("bunny")
    points = off_points(mesh)
    centre = points[1000]
    r = 0.08  # 5% of the diagonal
    strokes = script(tmp, "s.json", [
        {"tool": "label", "points": [centre], "radius": r, "falloff": "constant", "channels": {"label": 5}},
        {"tool": "sculpt", "points": [centre], "radius": 0.05, "amount": 0.01}])
    project = tmp / "bunny.meshpaint"
    done = run("paint", mesh, "--level", "2", "--strokes", str(strokes), "--save", str(project), "--quiet")
    assert done.returncode == 0, done.stderr
    outputs = {}
    for geometry in (False, True):
        out = tmp / f"scan_{geometry}.vtp"
        done = run("transfer", str(project), "--to", mesh, "-o", str(out), *(["--geometry"] if geometry else []))
        assert done.returncode == 0, done.stderr
        assert "scan vertices" in done.stderr
        outputs[geometry] = read_polydata(out)
    return points, centre, r, outputs


def test_transfer_keeps_the_scan_and_its_labels_match_the_stroke(bunny_transfer):
    points, centre, r, outputs = bunny_transfer
    scan = outputs[False]
    assert scan.GetNumberOfPoints() == len(points) and scan.GetNumberOfCells() == 75408
    label = scan.GetPointData().GetArray("label")
    for name, comps in (("diffuse", 3), ("specular", 3), ("roughness", 1), ("displacement", 1), ("label", 1)):
        assert scan.GetPointData().GetArray(name).GetNumberOfComponents() == comps
    inside = outside = 0
    for i, p in enumerate(points):
        assert dist(scan.GetPoint(i), p) < 1e-6  # same vertices, same order
        d = dist(p, centre)
        if d < 0.9 * r:
            assert label.GetValue(i) == 5, (i, d / r)
            inside += 1
        elif d > 1.1 * r:
            assert label.GetValue(i) == 0, (i, d / r)
            outside += 1
    assert inside > 100 and outside > 30000


def test_transfer_geometry_carries_the_sculpting_over(bunny_transfer):
    points, centre, _, outputs = bunny_transfer
    plain, moved = outputs[False], outputs[True]
    near = 0
    for i, p in enumerate(points):
        shift = dist(moved.GetPoint(i), plain.GetPoint(i))
        d = dist(p, centre)
        if d > 0.06:  # outside the sculpt brush and its limit-surface support: bit for bit
            assert moved.GetPoint(i) == plain.GetPoint(i), i
        elif d < 0.01:
            assert shift == pytest.approx(0.01, rel=0.3), i  # the full amount near the centre
            near += 1
    assert near > 0


def scan_with_arrays(plane, tmp_path, id_name):
    """The plane as a VTP scan with a point array `id_name` (100 + index) and
    a cell array quality (index / 10), and a painted project p.meshpaint of it."""
    import vtk
    reader = vtk.vtkOBJReader()
    reader.SetFileName(str(plane))
    reader.Update()
    scan = reader.GetOutput()
    ids = vtk.vtkIntArray()
    ids.SetName(id_name)
    for i in range(scan.GetNumberOfPoints()):
        ids.InsertNextValue(100 + i)
    scan.GetPointData().AddArray(ids)
    quality = vtk.vtkFloatArray()
    quality.SetName("quality")
    for i in range(scan.GetNumberOfCells()):
        quality.InsertNextValue(i / 10)
    scan.GetCellData().AddArray(quality)
    writer = vtk.vtkXMLPolyDataWriter()
    writer.SetFileName(str(tmp_path / "scan.vtp"))
    writer.SetInputData(scan)
    writer.Write()
    strokes = script(tmp_path, "s.json", [RED, LABEL], level=3)
    assert run("paint", str(plane), "--strokes", str(strokes), "--save", str(tmp_path / "p.meshpaint")).returncode == 0
    return scan


def test_transfer_keeps_every_array_of_a_vtp_scan(plane, tmp_path):
    scan = scan_with_arrays(plane, tmp_path, "scanner_id")
    r = run("transfer", str(tmp_path / "p.meshpaint"), "--to", str(tmp_path / "scan.vtp"), "-o", str(tmp_path / "o.vtp"))
    assert r.returncode == 0, r.stderr
    out = read_polydata(tmp_path / "o.vtp")
    assert out.GetNumberOfPoints() == scan.GetNumberOfPoints() and out.GetNumberOfCells() == scan.GetNumberOfCells()
    assert [out.GetPointData().GetArray("scanner_id").GetValue(i) for i in range(out.GetNumberOfPoints())] == \
        [100 + i for i in range(scan.GetNumberOfPoints())]
    assert out.GetCellData().GetArray("quality").GetValue(3) == pytest.approx(0.3)
    # the red stroke's corners (1, 1) and (3, 1) are scan vertices 6 and 8
    assert out.GetPointData().GetArray("diffuse").GetTuple3(6) == (1.0, 0.0, 0.0)
    assert out.GetPointData().GetArray("label").GetValue(7) == 0


def read_ply(path):
    """Header, vertex properties and faces (with their properties) of a binary little-endian PLY."""
    import numpy as np
    data = path.read_bytes()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().splitlines()
    assert header[0] == "ply" and header[1] == "format binary_little_endian 1.0", header
    elements, current = {}, None
    for line in header[2:]:
        words = line.split()
        if words[0] == "element":
            current = elements.setdefault(words[1], {"count": int(words[2]), "props": []})
        elif words[0] == "property":
            current["props"].append(words[1:])
    types = {"float": "<f4", "int": "<i4", "uchar": "u1"}
    vertex = elements["vertex"]
    dtype = np.dtype([(p[1], types[p[0]]) for p in vertex["props"]])
    vertices = np.frombuffer(data, dtype=dtype, count=vertex["count"], offset=end)
    at = end + dtype.itemsize * vertex["count"]
    faces = []
    for _ in range(elements["face"]["count"]):
        face = {}
        for p in elements["face"]["props"]:
            if p[0] == "list":
                n = data[at]
                face[p[3]] = list(np.frombuffer(data, dtype="<i4", count=n, offset=at + 1))
                at += 1 + 4 * n
            else:
                face[p[1]] = np.frombuffer(data, dtype=types[p[0]], count=1, offset=at)[0]
                at += 4
        faces.append(face)
    assert at == len(data)
    return vertices, faces


def test_transfer_to_ply_keeps_every_array_as_properties(plane, tmp_path):
    import vtk
    scan = scan_with_arrays(plane, tmp_path, "scanner id")
    r = run("transfer", str(tmp_path / "p.meshpaint"), "--to", str(tmp_path / "scan.vtp"), "-o", str(tmp_path / "o.ply"))
    assert r.returncode == 0, r.stderr
    vertices, faces = read_ply(tmp_path / "o.ply")
    assert len(vertices) == 25 and len(faces) == 16
    assert list(vertices["scanner_id"]) == [100 + i for i in range(25)]
    assert [(vertices[k]["x"], vertices[k]["y"]) for k in range(25)] == [(x, y) for y in range(5) for x in range(5)]
    assert (vertices["diffuse_r"][6], vertices["diffuse_g"][6], vertices["diffuse_b"][6]) == (1, 0, 0)
    assert vertices["label"].dtype.kind == "i" and vertices["label"][7] == 0
    for k in range(16):
        cell = vtk.vtkIdList()
        scan.GetCellPoints(k, cell)
        assert faces[k]["vertex_indices"] == [cell.GetId(i) for i in range(cell.GetNumberOfIds())]
        assert faces[k]["quality"] == pytest.approx(k / 10)


@pytest.mark.parametrize("args, message", [
    (["{plane}", "--to", "{plane}", "-o", "{tmp}/o.vtp"], r"transfer needs a project \(.meshpaint\), not '.*plane.obj'"),
    (["{project}", "-o", "{tmp}/o.vtp"], r"--to SCAN is required"),
    (["{project}", "--to", "{plane}", "-o", "{tmp}/o.stl"], r"unknown format '.stl' \(.vtp, .ply\)"),
    (["{project}", "--to", "{tmp}/nothing.off", "-o", "{tmp}/o.vtp"], r"cannot open '.*nothing.off': no such file"),
    (["{project}", "--to", "{tmp}/s.json", "-o", "{tmp}/o.vtp"], r"unknown format '.json'"),
])
def test_transfer_arguments_are_checked(plane, tmp_path, args, message):
    project = tmp_path / "p.meshpaint"
    (tmp_path / "s.json").write_text("{}")
    assert run("paint", str(plane), "--save", str(project)).returncode == 0
    r = run("transfer", *[a.format(plane=plane, project=project, tmp=tmp_path) for a in args])
    lines = r.stderr.strip().splitlines()
    assert r.returncode == 2 and len(lines) == 1, r.stderr
    assert re.search(message, lines[0]), lines[0]
    assert not (tmp_path / "o.vtp").exists()
