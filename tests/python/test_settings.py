"""meshpaint from Python leaves VTK's global state alone, and refuses settings
out of range or in conflict instead of clamping or overriding them."""
import json
import os
import subprocess
import sys

import pytest
import vtk

import meshpaint

STROKE = {"points": [[0, 0, 0.5]], "radius": 0.2, "channels": {"diffuse": [1, 0, 0]}}


def sphere():
    src = vtk.vtkSphereSource()
    src.Update()
    return src.GetOutput()


def run_python(code, env=None):
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300,
                          env=dict(os.environ, **(env or {})))


def test_update_keeps_vtk_warnings_on_and_later_errors_reported():
    r = run_python("""
import vtk, meshpaint
good = meshpaint.vtkPaintSurface()
src = vtk.vtkSphereSource(); src.Update()
good.SetInputData(src.GetOutput()); good.Update()
bad = meshpaint.vtkPaintSurface(); bad.SetInputData(vtk.vtkPolyData())
try:
    bad.Update()
except meshpaint.Error as e:
    print("raised:", e)
print("display:", vtk.vtkObject.GetGlobalWarningDisplay())
reader = vtk.vtkXMLPolyDataReader(); reader.SetFileName("/nonexistent/scan.vtp"); reader.Update()
""")
    assert r.returncode == 0, r.stderr
    assert "raised: " in r.stdout and "has no faces" in r.stdout
    assert "display: 1" in r.stdout
    # The later pipeline's failure is still reported by VTK ...
    assert "vtkXMLPolyDataReader" in r.stderr, r.stderr
    # ... while meshpaint's own failure was raised, not printed as well.
    assert "vtkPaintSurface" not in r.stderr, r.stderr


@pytest.mark.parametrize("level", [0, 13, 20, -1])
def test_painting_levels_out_of_range_raise(level):
    s = meshpaint.vtkPaintSurface()
    with pytest.raises(meshpaint.Error, match="painting level must be from 1 to 12, not %d" % level):
        s.SetLevel(level)
    assert s.GetLevel() == 3
    s.SetLevel(12)
    assert s.GetLevel() == 12
    with pytest.raises(meshpaint.Error, match="model level must be from 0"):
        s.SetModelLevel(level if level < 0 else 13)


def test_other_ranged_settings_raise_instead_of_clamping():
    f = meshpaint.vtkCatmullClarkAtlasFilter()
    with pytest.raises(meshpaint.Error, match="Level must be from 1 to 12, not 20"):
        f.SetLevel(20)
    f.SetLevel(4)
    assert f.GetLevel() == 4
    p = meshpaint.vtkSurfacePicker()
    with pytest.raises(meshpaint.Error, match="PatchResolution must be from 0"):
        p.SetPatchResolution(-1)
    v = meshpaint.vtkPaintView()
    with pytest.raises(meshpaint.Error, match="Level must be from 1 to 12, not 0"):
        v.SetLevel(0)
    with pytest.raises(meshpaint.Error, match=r"^UndoBudget must be from 0 to 1,000,000,000, not -0.5$"):
        v.SetUndoBudget(-0.5)


def test_a_script_level_conflicting_with_set_level_raises():
    s = meshpaint.vtkPaintSurface()
    s.SetInputData(sphere())
    s.SetLevel(4)
    with pytest.raises(meshpaint.Error, match=r'"level" 2 conflicts with the painting level 4'):
        s.ApplyStrokes(json.dumps({"level": 2, "strokes": [STROKE]}))
    s.ApplyStrokes(json.dumps({"level": 4, "strokes": [STROKE]}))  # agreeing is fine
    s.Update()
    assert s.GetStrokeCount() == 1


def test_a_script_level_is_taken_when_none_was_chosen_then_kept():
    s = meshpaint.vtkPaintSurface()
    s.SetInputData(sphere())
    s.ApplyStrokes(json.dumps({"level": 2, "strokes": [STROKE]}))
    assert s.GetLevel() == 2
    with pytest.raises(meshpaint.Error, match=r'"level" 5 conflicts with the painting level 2'):
        s.ApplyStrokes(json.dumps({"level": 5, "strokes": [STROKE]}))
    s.Update()
    with pytest.raises(meshpaint.Error, match="conflicts"):
        s.ApplyStrokes(json.dumps({"level": 3, "strokes": [STROKE]}))


def test_to_pyvista_without_pyvista_says_how_to_install_it():
    try:
        import pyvista  # noqa: F401
        pytest.skip("PyVista is importable here; tests/python/test_pyvista.py covers it")
    except ImportError:
        pass
    with pytest.raises(meshpaint.Error, match="docs/python.md"):
        meshpaint.to_pyvista(sphere())


def test_a_second_vtk_is_refused_at_import(tmp_path):
    # A stand-in for pip's vtk found before Debian's.
    fake = tmp_path / "vtkmodules"
    fake.mkdir()
    (fake / "__init__.py").write_text("")
    (fake / "vtkCommonCore.py").write_text(
        "class vtkVersion:\n    @staticmethod\n    def GetVTKVersion():\n        return '9.5.2'\n")
    r = run_python("import meshpaint", env={"PYTHONPATH": str(tmp_path) + os.pathsep + os.environ["PYTHONPATH"]})
    assert r.returncode == 1
    assert "ImportError: meshpaint is built for VTK 9.1" in r.stderr, r.stderr
    assert "imports VTK 9.5.2" in r.stderr
