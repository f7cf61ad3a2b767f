"""meshpaint.batch: batches over scans on Dask clusters of worker processes.

Run by CTest with PYTHONPATH=build/python and MESHPAINT_SOURCE_DIR set; the
batch finds build/bin/meshpaint beside the package, as a user's would.
"""
import csv
import json
import os
import shutil
import subprocess
import sys

import pytest
import vtk
from distributed import Client, LocalCluster, get_task_stream

import meshpaint
from meshpaint import batch, scan_job

SOURCE = os.environ["MESHPAINT_SOURCE_DIR"]
SCANS = os.path.join(SOURCE, "data", "scans")
CUBE = os.path.join(SOURCE, "tests", "support", "cube.obj")
BROKEN = os.path.join(SOURCE, "tests", "bad_input", "garbage.off")

STROKES = '{"strokes": [{"tool": "wash", "channels": {"label": 1, "diffuse": [0.8, 0.2, 0.1]}}]}'
LABELS = '[{"id": 1, "name": "bone", "colour": [0.9, 0.85, 0.7]}]'
RESULTS = {"project.meshpaint", "surface.vtp", "model.obj", "model.mtl", "diffuse.png", "scan.vtp", "stats.csv"}


def need_scans(*names):
    paths = [os.path.join(SCANS, n) for n in names]
    missing = [p for p in paths if not os.path.exists(p)]
    if missing:
        pytest.skip(f"{missing[0]} missing (scripts/fetch-scans.sh)")
    return paths


def triangles_and_vertices(path):
    """Counted from the file itself (OFF or OBJ), polygons fanned: what the summary should say."""
    with open(path) as f:
        lines = [l.split() for l in f if l.strip() and not l.startswith("#")]
    if path.endswith(".off"):
        vertices, faces = int(lines[1][0]), int(lines[1][1])
        polys = lines[2 + vertices:2 + vertices + faces]
        return sum(int(p[0]) - 2 for p in polys), vertices
    return sum(len(l) - 3 for l in lines if l[0] == "f"), sum(l[0] == "v" for l in lines)


def read_vtp(path):
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(str(path))
    reader.Update()
    return reader.GetOutput()


def read_summary(folder):
    with open(os.path.join(folder, "summary.csv"), newline="") as f:
        return list(csv.DictReader(f))


def write_inputs(tmp_path):
    (tmp_path / "s.json").write_text(STROKES)
    (tmp_path / "labels.json").write_text(LABELS)
    return str(tmp_path / "s.json"), str(tmp_path / "labels.json")


def hidden_leftovers(folder):
    return [n for n in os.listdir(folder) if n.startswith(".")]


@pytest.fixture(scope="module")
def cluster():
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as c:
        yield c


def test_six_scans_on_two_workers_five_results_and_one_recorded_failure(cluster, tmp_path):
    good = need_scans("femur.off", "lion-head.off", "ChineseDragon-10kv.off", "bunny00.off")
    other = tmp_path / "other" / "femur.obj"  # same name as a scan above: gets a folder of its own
    other.parent.mkdir()
    shutil.copy(CUBE, other)
    scans = good[:2] + [BROKEN] + good[2:] + [str(other)]
    strokes, labels = write_inputs(tmp_path)
    out = tmp_path / "out"
    seen = []
    with Client(cluster) as client, get_task_stream(client) as stream:
        rows = meshpaint.batch.run(scans, strokes=strokes, output=out, fit=True, labels=labels, level=1,
                                   client=client, progress=seen.append)
    assert len({task["worker"] for task in stream.data}) == 2  # both worker processes took scans
    assert len(seen) == 6
    assert [r["scan"] for r in rows] == ["femur", "lion-head", "garbage", "ChineseDragon-10kv", "bunny00", "femur-2"]
    assert [r["status"] for r in rows] == ["ok", "ok", "failed", "ok", "ok", "ok"]

    failed = rows[2]
    assert failed["error"].startswith("meshpaint fit: ") and BROKEN in failed["error"], failed
    assert "\n" not in failed["error"]
    assert failed["triangles"] is None and failed["fit_rms_percent"] is None
    assert not (out / "garbage").exists()
    assert failed["error"] in (out / "logs" / "garbage.log").read_text()

    for row, scan in zip(rows, scans):
        if row["status"] != "ok":
            continue
        folder = out / row["scan"]
        assert RESULTS <= set(os.listdir(folder)), row
        assert row["error"] == "" and row["seconds"] > 0 and row["path"] == scan
        triangles, vertices = triangles_and_vertices(scan)
        assert row["triangles"] == triangles
        # fit's own report (both directions) against the summary's figures
        report = json.loads((folder / "fit.json").read_text())
        assert (row["fit_rms_percent"], row["fit_worst_percent"]) == scan_job.fit_errors(str(folder / "fit.json"))
        assert row["fit_rms_percent"] == max(report["scan_to_fit"]["rms_percent"], report["fit_to_scan"]["rms_percent"])
        assert row["fit_worst_percent"] == max(report["scan_to_fit"]["max_percent"], report["fit_to_scan"]["max_percent"])
        assert report["mode"] == "decimated" and report["base_faces"] <= report["budget"]
        assert 0 < row["fit_rms_percent"] <= row["fit_worst_percent"]
        # the wash labelled everything 1, named by the labels file, on the surface and on the scan
        with open(folder / "stats.csv", newline="") as f:
            stats = list(csv.DictReader(f))
        assert [(s["id"], s["name"], float(s["area_fraction"])) for s in stats] == [("1", "bone", 1.0)]
        scan_out = read_vtp(folder / "scan.vtp")
        assert scan_out.GetNumberOfPoints() == vertices
        assert scan_out.GetPointData().GetArray("label").GetRange() == (1.0, 1.0)
        assert read_vtp(folder / "surface.vtp").GetPointData().GetArray("label").GetRange() == (1.0, 1.0)

    summary = read_summary(out)
    expected = batch.summary_csv(rows).splitlines()
    assert list(summary[0].keys()) == expected[0].split(",")
    assert list(summary[0].keys())[:7] == ["scan", "status", "triangles", "fit_rms_percent", "fit_worst_percent",
                                          "seconds", "error"]
    assert [r["scan"] for r in summary] == [r["scan"] for r in rows]
    assert summary[2]["error"] == failed["error"] and summary[2]["triangles"] == ""
    assert [int(r["triangles"]) for r in summary if r["status"] == "ok"] == [r["triangles"] for r in rows
                                                                           if r["status"] == "ok"]
    assert hidden_leftovers(out) == []


def run_cli(*args):
    return subprocess.run([sys.executable, "-m", "meshpaint.batch", *args], capture_output=True, text=True,
                          timeout=600)


def test_command_line_exit_codes_and_a_safe_rerun(cluster, tmp_path):
    strokes, _ = write_inputs(tmp_path)
    out = tmp_path / "out"
    # Its own LocalCluster: one scan fails, so the exit status is 4 and the summary says which.
    r = run_cli(CUBE, BROKEN, "--strokes", strokes, "--level", "2", "--workers", "2", "-o", str(out))
    assert r.returncode == 4, r.stderr
    assert r.stderr.splitlines()[-1] == f"meshpaint.batch: 1 of 2 scans failed (see {out}/summary.csv)"
    assert [(s["scan"], s["status"], s["fit_rms_percent"]) for s in read_summary(out)] == [
        ("cube", "ok", ""), ("garbage", "failed", "")]
    assert read_summary(out)[1]["error"].startswith("meshpaint paint: ")
    # Run again over the same folder on an existing cluster: the scan's folder is replaced whole.
    (out / "cube" / "stale.txt").write_text("from an earlier run")
    r = run_cli(CUBE, "--strokes", strokes, "--level", "2", "--scheduler", cluster.scheduler_address,
                "--quiet", "-o", str(out))
    assert r.returncode == 0, r.stderr
    assert r.stderr == ""
    assert RESULTS <= set(os.listdir(out / "cube")) and not (out / "cube" / "stale.txt").exists()
    assert [s["status"] for s in read_summary(out)] == ["ok"]
    assert read_vtp(out / "cube" / "surface.vtp").GetNumberOfCells() == 6 * 4 ** 2
    assert hidden_leftovers(out) == []


@pytest.mark.parametrize("args, message", [
    (["--strokes", "missing.json"], "cannot read stroke script"),
    (["--strokes", "{strokes}", "--labels", "{strokes}.nope"], "cannot read labels file"),
    (["--strokes", "{strokes}", "--workers", "2", "--scheduler", "tcp://127.0.0.1:1"], "not allowed with"),
    (["--strokes", "{strokes}", "--level", "13"], "level must be"),
    (["--strokes", "{strokes}", "--workers", "0"], "workers must be"),
])
def test_bad_arguments_give_one_line_and_exit_2_before_any_scan(tmp_path, args, message):
    strokes, _ = write_inputs(tmp_path)
    r = run_cli(CUBE, *[a.format(strokes=strokes) for a in args], "-o", str(tmp_path / "out"))
    assert r.returncode == 2, r.stderr
    assert len(r.stderr.splitlines()) == 1 and message in r.stderr, r.stderr
    assert not (tmp_path / "out" / "cube").exists()


def test_a_stroke_script_that_is_not_json_is_refused(tmp_path):
    (tmp_path / "bad.json").write_text('{"strokes": [')
    r = run_cli(CUBE, "--strokes", str(tmp_path / "bad.json"), "-o", str(tmp_path / "out"))
    assert r.returncode == 2 and "is not JSON" in r.stderr and len(r.stderr.splitlines()) == 1, r.stderr


def test_unreachable_scheduler_exits_3(tmp_path):
    strokes, _ = write_inputs(tmp_path)
    with socket_that_refuses() as address:
        r = subprocess.run([sys.executable, "-m", "meshpaint.batch", CUBE, "--strokes", strokes, "--scheduler", address,
                            "-o", str(tmp_path / "out")], capture_output=True, text=True, timeout=600,
                           env=dict(os.environ, DASK_DISTRIBUTED__COMM__TIMEOUTS__CONNECT="2s"))
    assert r.returncode == 3, r.stderr
    assert r.stderr.startswith("meshpaint.batch: cannot reach the scheduler"), r.stderr


class socket_that_refuses:
    """A local TCP address with nothing listening on it."""

    def __enter__(self):
        import socket
        self.s = socket.socket()
        self.s.bind(("127.0.0.1", 0))  # bound, never listening: connections are refused
        return f"tcp://127.0.0.1:{self.s.getsockname()[1]}"

    def __exit__(self, *exc):
        self.s.close()


def fake_meshpaint(tmp_path, body):
    """A stand-in program for the steps, to make a scan crash or hang."""
    path = tmp_path / "fake-meshpaint"
    path.write_text("#!/bin/sh\n" + body + "\n")
    path.chmod(0o755)
    return str(path)


@pytest.mark.parametrize("body, timeout, error", [
    ("kill -SEGV $$", 60, "meshpaint paint: killed by signal SIGSEGV"),
    ("exec sleep 60", 1, "meshpaint paint: timed out (the scan's time limit is 1 s)"),
    ("echo 'meshpaint paint: no memory left on the device' >&2; exit 3",
     60, "meshpaint paint: no memory left on the device"),
])
def test_a_crashing_or_hanging_step_fails_only_its_scan(tmp_path, body, timeout, error):
    strokes, _ = write_inputs(tmp_path)
    (tmp_path / "out" / "cube").mkdir(parents=True)
    (tmp_path / "out" / "cube" / "earlier.txt").write_text("kept")
    row = scan_job.process_scan(CUBE, "cube", str(tmp_path / "out"), strokes, timeout=timeout,
                                executable=fake_meshpaint(tmp_path, body))
    assert (row["status"], row["error"]) == ("failed", error)
    # a failed run leaves the earlier results as they were, and no temporary folder
    assert os.listdir(tmp_path / "out" / "cube") == ["earlier.txt"]
    assert hidden_leftovers(tmp_path / "out") == []
    assert error in (tmp_path / "out" / "logs" / "cube.log").read_text()


def test_scan_names_are_unique_and_avoid_the_batch_files():
    assert batch.scan_names(["a/bunny.off", "b/bunny.ply", "logs.obj", "summary.csv.off", "c/bunny.off"]) == [
        "bunny", "bunny-2", "logs-2", "summary.csv-2", "bunny-3"]


def test_run_refuses_bad_arguments_before_starting_a_cluster(tmp_path):
    strokes, _ = write_inputs(tmp_path)
    with pytest.raises(meshpaint.Error, match="no scans given"):
        batch.run([], strokes, tmp_path / "out")
    with pytest.raises(meshpaint.Error, match="cannot read labels file"):
        batch.run([CUBE], strokes, tmp_path / "out", labels=tmp_path / "none.json")
    with pytest.raises(meshpaint.Error, match="workers must be"):
        batch.run([CUBE], strokes, tmp_path / "out", client=object(), workers=2)
    assert not (tmp_path / "out").exists()
