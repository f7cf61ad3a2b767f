"""meshpaint fit: scans turned into projects, the fit error on real scans,
and smoothing a fitted scan. Run by CTest like test_cli.py."""
import json
import math
import os
import random
import re

import pytest
import vtk

from test_cli import SCANS, read_polydata, run


def fit_numbers(stdout):
    """The % of the diagonal of the four error figures: scan->fit RMS, max, fit->scan RMS, max."""
    out = {}
    for key in ("scan->fit", "fit->scan"):
        line = next(l for l in stdout.splitlines() if l.startswith(key))
        rms, worst = re.findall(r"\(([0-9.]+)%\)", line)
        out[key] = (float(rms), float(worst))
    return out


@pytest.mark.parametrize("scan", ["bunny00.off", "refined_elephant.off"])
def test_fit_error_of_real_scans_is_within_the_targets(tmp_path, scan):
    path = os.path.join(SCANS, scan)
    if not os.path.exists(path):
        pytest.skip(f"data/scans/{scan} missing (scripts/fetch-scans.sh)")
    r = run("fit", path, "-o", str(tmp_path / "f.meshpaint"))
    assert r.returncode == 0, r.stderr
    assert "decimated to" in r.stdout
    assert "meshpaint fit: pass 2 of 2" in r.stderr  # progress
    errors = fit_numbers(r.stdout)
    for key in ("scan->fit", "fit->scan"):
        rms, worst = errors[key]
        assert rms <= 0.1 and worst <= 0.5, (key, rms, worst)
    info = run("info", str(tmp_path / "f.meshpaint")).stdout
    assert re.search(r"^scan +" + re.escape(path) + r", [0-9,]+ bytes, CRC-32 [0-9a-f]{8}$", info, re.M), info


def noisy_sphere(path, sigma=0.01, seed=3):
    """A unit icosphere (2,562 vertices), each vertex moved radially by Gaussian noise of `sigma`."""
    src = vtk.vtkPlatonicSolidSource()
    src.SetSolidTypeToIcosahedron()
    sub = vtk.vtkLinearSubdivisionFilter()
    sub.SetInputConnection(src.GetOutputPort())
    sub.SetNumberOfSubdivisions(4)
    clean = vtk.vtkCleanPolyData()
    clean.SetInputConnection(sub.GetOutputPort())
    clean.Update()
    poly = clean.GetOutput()
    rng = random.Random(seed)
    pts = poly.GetPoints()
    for i in range(pts.GetNumberOfPoints()):
        p = pts.GetPoint(i)
        s = (1 + rng.gauss(0, sigma)) / math.sqrt(sum(x * x for x in p))
        pts.SetPoint(i, [x * s for x in p])
    writer = vtk.vtkPLYWriter()
    writer.SetFileName(str(path))
    writer.SetInputData(poly)
    writer.Write()


def volume_and_noise(poly):
    """Enclosed volume (vtkMassProperties), and the noise: the RMS deviation
    of the vertices' distances from the centre around their mean."""
    tri = vtk.vtkTriangleFilter()
    tri.SetInputData(poly)
    mass = vtk.vtkMassProperties()
    mass.SetInputConnection(tri.GetOutputPort())
    mass.Update()
    radii = [math.sqrt(sum(x * x for x in poly.GetPoint(i))) for i in range(poly.GetNumberOfPoints())]
    mean = sum(radii) / len(radii)
    return mass.GetVolume(), math.sqrt(sum((r - mean) ** 2 for r in radii) / len(radii))


def smoothed_scan(tmp_path, project, scan, method):
    strokes = tmp_path / f"{method}.json"
    strokes.write_text(json.dumps({"strokes": [
        {"tool": "smooth", "points": [[1, 0, 0]], "radius": 4, "falloff": "constant", "iterations": 20,
         "method": method}]}))
    smoothed = tmp_path / f"{method}.meshpaint"
    r = run("paint", str(project), "--strokes", str(strokes), "--save", str(smoothed), "--quiet")
    assert r.returncode == 0, r.stderr
    out = tmp_path / f"{method}.vtp"
    r = run("transfer", str(smoothed), "--to", str(scan), "-o", str(out), "--geometry", "--quiet")
    assert r.returncode == 0, r.stderr
    return volume_and_noise(read_polydata(out))


def test_taubin_smoothing_of_a_fitted_scan_keeps_its_volume_and_lowers_its_noise(tmp_path):
    """A noisy sphere scan (1% radial noise) is fitted, its whole surface
    smoothed (20 passes at full weight) and the result carried back onto the
    scan's vertices. Taubin keeps the enclosed volume within 0.5% while the
    noise (RMS of the radius around its mean) goes down; Laplacian
    smoothing, for contrast, loses more than 0.5% of the volume."""
    scan = tmp_path / "noisy.ply"
    noisy_sphere(scan)
    project = tmp_path / "sphere.meshpaint"
    r = run("fit", str(scan), "-o", str(project), "--quiet")
    assert r.returncode == 0, r.stderr
    volume, noise = volume_and_noise(read_polydata(scan))
    assert noise == pytest.approx(0.01, rel=0.1)
    taubin_volume, taubin_noise = smoothed_scan(tmp_path, project, scan, "taubin")
    assert abs(taubin_volume - volume) / volume < 0.005
    assert taubin_noise < 0.92 * noise
    laplacian_volume, laplacian_noise = smoothed_scan(tmp_path, project, scan, "laplacian")
    assert (volume - laplacian_volume) / volume > 0.005
    assert laplacian_noise < noise


def test_fit_direct_uses_the_scan_as_base_mesh(tmp_path):
    scan = tmp_path / "noisy.ply"
    noisy_sphere(scan)
    r = run("fit", str(scan), "--direct", "--level", "2", "-o", str(tmp_path / "d.meshpaint"))
    assert r.returncode == 0, r.stderr
    assert "base mesh  direct: the scan is the base mesh" in r.stdout
    assert "15,360 patches" in r.stdout  # three quads per triangle
    errors = fit_numbers(r.stdout)
    assert errors["fit->scan"][0] < 0.1


def test_transfer_warns_when_the_scan_is_not_the_fitted_one(tmp_path):
    scan = tmp_path / "noisy.ply"
    noisy_sphere(scan)
    other = tmp_path / "other.ply"
    noisy_sphere(other, seed=4)
    assert run("fit", str(scan), "-o", str(tmp_path / "f.meshpaint"), "--quiet").returncode == 0
    r = run("transfer", str(tmp_path / "f.meshpaint"), "--to", str(other), "-o", str(tmp_path / "o.vtp"), "--quiet")
    assert r.returncode == 0, r.stderr
    assert r.stderr.strip() == f"meshpaint transfer: warning: {other} is not the file the project was fitted to ({scan})"


@pytest.mark.parametrize("args, message", [
    (["-o", "{tmp}/f.vtp"], r"-o needs a file name ending in .meshpaint, not '.*f.vtp'"),
    ([], r"-o PROJECT.meshpaint is required"),
    (["--direct", "--base-faces", "100", "-o", "{tmp}/f.meshpaint"], r"--base-faces and --direct exclude each other"),
    (["--base-faces", "2", "-o", "{tmp}/f.meshpaint"], r"--base-faces must be an integer from 4 to 10000000, not '2'"),
])
def test_fit_arguments_are_checked(tmp_path, args, message):
    scan = tmp_path / "noisy.ply"
    noisy_sphere(scan)
    r = run("fit", str(scan), *[a.format(tmp=tmp_path) for a in args])
    lines = r.stderr.strip().splitlines()
    assert r.returncode == 2 and len(lines) == 1, r.stderr
    assert re.search(message, lines[0]), lines[0]
