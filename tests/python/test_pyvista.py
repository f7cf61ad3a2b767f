"""meshpaint under PyVista: the pinned PyVista of scripts/pyvista-requirements.txt,
installed over Debian's VTK into a venv by scripts/pyvista-venv.sh (docs/python.md).
Skipped, saying why, when the venv cannot be made (no network)."""
import json
import os
import re
import subprocess

import pytest

SOURCE = os.environ["MESHPAINT_SOURCE_DIR"]
VENV = os.environ.get("MESHPAINT_PYVISTA_VENV", "")


@pytest.fixture(scope="module")
def venv_python():
    if not VENV:
        pytest.skip("MESHPAINT_PYVISTA_VENV is not set (ctest sets it to build/pyvista-venv)")
    try:
        r = subprocess.run([os.path.join(SOURCE, "scripts", "pyvista-venv.sh"), VENV], capture_output=True,
                           text=True, timeout=600)
    except subprocess.TimeoutExpired:
        pytest.skip("cannot make the PyVista venv: pip took more than 10 minutes (network?)")
    if r.returncode != 0:
        said = (r.stderr.strip() or r.stdout.strip()).splitlines()
        pytest.skip("cannot make the PyVista venv at %s (no network to PyPI?): %s" % (VENV, said[-1] if said else
                                                                                        "exit %d" % r.returncode))
    return os.path.join(VENV, "bin", "python")


def pinned_pyvista():
    with open(os.path.join(SOURCE, "scripts", "pyvista-requirements.txt")) as f:
        return re.search(r"^pyvista==(\S+)", f.read(), re.M).group(1)


def test_outputs_wrap_as_pyvista_meshes(venv_python):
    r = subprocess.run([venv_python, "-c", """
import json, numpy as np, vtk, pyvista, meshpaint
src = vtk.vtkSphereSource(); src.Update()
s = meshpaint.vtkPaintSurface(); s.SetInputData(src.GetOutput()); s.SetLevel(3)
s.ApplyStrokes(json.dumps({"strokes": [{"points": [[0, 0, 0.5]], "radius": 0.2,
                                        "channels": {"diffuse": [1, 0, 0]}}]}))
mesh = meshpaint.to_pyvista(s)
wrapped = pyvista.wrap(s.GetOutput())
f = meshpaint.vtkCatmullClarkAtlasFilter(); f.SetInputData(src.GetOutput()); f.SetLevel(2); f.Update()
subdivided = pyvista.wrap(f.GetOutput())
diffuse = mesh.point_data["diffuse"]
print(json.dumps({
    "pyvista": pyvista.__version__, "vtk": list(pyvista.vtk_version_info),
    "type": type(mesh).__name__, "points": mesh.n_points, "vtk_points": s.GetOutput().GetNumberOfPoints(),
    "arrays": sorted(mesh.point_data.keys()), "red": int((diffuse[:, 1] == 0).sum()),
    "same_points": bool(np.array_equal(wrapped.points, mesh.points)),
    "subdivided": [type(subdivided).__name__, subdivided.n_cells, f.GetOutput().GetNumberOfCells()]}))
"""], capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    got = json.loads(r.stdout.strip().splitlines()[-1])
    assert got["pyvista"] == pinned_pyvista()
    assert got["vtk"][:2] == [9, 1]  # Debian's VTK, not a second one
    assert got["type"] == "PolyData"
    assert got["points"] == got["vtk_points"] > 0
    for name in ("diffuse", "specular", "roughness", "displacement", "label", "Normals"):
        assert name in got["arrays"], got["arrays"]
    assert got["red"] > 0
    assert got["same_points"]
    assert got["subdivided"][0] == "PolyData" and got["subdivided"][1] == got["subdivided"][2] > 0


def test_the_venv_holds_no_second_vtk(venv_python):
    r = subprocess.run([venv_python, "-m", "pip", "show", "vtk"], capture_output=True, text=True, timeout=120)
    assert r.returncode != 0, r.stdout
    r = subprocess.run([venv_python, "-c", "import vtkmodules; print(vtkmodules.__file__)"], capture_output=True,
                       text=True, timeout=120)
    assert r.stdout.startswith("/usr/lib/python3/"), r.stdout + r.stderr
