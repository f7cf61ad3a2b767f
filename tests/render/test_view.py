"""The painting window driven by synthetic mouse and key events, offscreen.

A session's recording, replayed headless by `meshpaint paint`, must give
the same surface bit for bit. Run by CTest under xvfb-run (see test_render.py).
"""
import json
import os
import subprocess

import pytest

import vtk
import vtkmodules.vtkInteractionStyle  # noqa: F401  (the interactor's defaults)
import vtkmodules.vtkRenderingFreeType  # noqa: F401  (on-screen text)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL window)
from vtkmodules.util.numpy_support import vtk_to_numpy

import meshpaint

BIN = os.environ["MESHPAINT_BIN"]
CUBE = os.path.join(os.environ["MESHPAINT_SOURCE_DIR"], "tests", "support", "cube.obj")
SIZE = (400, 300)


def open_view(tmp_path, level=4, share=True, mesh=CUBE):
    view = meshpaint.vtkPaintView()
    view.SetShareArrays(share)
    view.SetLevel(level)
    view.SetSize(*SIZE)
    view.OffScreenOn()
    view.SetSaveDirectory(str(tmp_path / "session"))
    assert view.LoadMesh(str(mesh)), view.GetLastError()
    assert view.Initialize(), view.GetLastError()
    return view


def event(view, name, x=0, y=0, ctrl=False, shift=False, key=None):
    view.GetInteractor().SetEventInformation(x, y, int(ctrl), int(shift), "\0", 0, key)
    view.GetInteractor().InvokeEvent(name)


def key(view, keysym, ctrl=False, shift=False):
    event(view, "KeyPressEvent", ctrl=ctrl, shift=shift, key=keysym)


def drag(view, points):
    x, y = points[0]
    event(view, "MouseMoveEvent", x, y)
    event(view, "LeftButtonPressEvent", x, y)
    for x, y in points[1:]:
        event(view, "MouseMoveEvent", x, y)
    event(view, "LeftButtonReleaseEvent", x, y)


def read_vtp(path):
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(str(path))
    reader.Update()
    return reader.GetOutput()


def arrays(poly):
    """Points and every point array, as numpy arrays by name."""
    out = {"points": vtk_to_numpy(poly.GetPoints().GetData())}
    pd = poly.GetPointData()
    for k in range(pd.GetNumberOfArrays()):
        out[pd.GetArrayName(k)] = vtk_to_numpy(pd.GetArray(k))
    return out


def line(x0, y0, x1, y1, steps=20):
    return [(x0 + (x1 - x0) * k // steps, y0 + (y1 - y0) * k // steps) for k in range(steps + 1)]


@pytest.mark.parametrize("share", [True, False])
def test_recorded_session_replays_to_the_same_bits(tmp_path, share):
    view = open_view(tmp_path, share=share)
    # PoCL's memory is the host's: the window draws the engine's arrays.
    assert view.IsSharingArrays(0) == (share and "gpu" not in os.environ.get("MESHPAINT_DEVICE", ""))
    shown = view.GetPicker().GetActor().GetMapper().GetInput()
    colour, points = shown.GetPointData().GetArray("diffuse"), shown.GetPoints().GetData()
    colour_time, points_time = colour.GetMTime(), points.GetMTime()
    # Paint red across the front face, change tool, colour, size; sculpt,
    # undo it, redo it; then a blue stroke with mirror on x.
    drag(view, line(150, 120, 260, 180))
    # the colours are marked for upload, the untouched points are not
    assert colour.GetMTime() > colour_time and points.GetMTime() == points_time
    # and the renderer took them: the stroke shows red in the window
    view.Render()
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(view.GetRenderWindow())
    grab.ReadFrontBufferOff()
    grab.Update()
    rgb = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).astype(int)
    assert ((rgb[:, 0] > 120) & (rgb[:, 1] < 60) & (rgb[:, 2] < 60)).sum() > 200
    key(view, "t", shift=True)  # previous tool from paint: label
    key(view, "t")              # paint again
    key(view, "6")              # blue swatch
    key(view, "bracketright")
    key(view, "m")              # mirror x
    drag(view, line(170, 200, 230, 110))
    for _ in range(3):
        key(view, "t")          # paint -> smooth -> blur -> sculpt
    drag(view, line(200, 150, 215, 160, 5))
    key(view, "z", ctrl=True)
    key(view, "y", ctrl=True)
    key(view, "s", ctrl=True)   # save: strokes.json + surface.vtp
    session = tmp_path / "session"
    script = json.loads((session / "strokes.json").read_text())
    assert script["level"] == 4
    assert [s["tool"] for s in script["strokes"]] == ["paint", "paint", "sculpt"]
    assert script["strokes"][1]["mirror"] == "x"

    replay = tmp_path / "replay"
    r = subprocess.run([BIN, "paint", CUBE, "--strokes", str(session / "strokes.json"), "-o", str(replay)],
                       capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    live, again = arrays(read_vtp(session / "surface.vtp")), arrays(read_vtp(replay / "surface.vtp"))
    assert live.keys() == again.keys()
    for name in live:
        assert live[name].tobytes() == again[name].tobytes(), name
    # The window shows what was saved: its arrays, brought up to date from
    # the changed patches alone while painting, equal a full read.
    drawn = arrays(view.GetPicker().GetActor().GetMapper().GetInput())
    for name in ("points", "Normals", "diffuse", "specular", "roughness", "displacement", "label", "mask"):
        assert drawn[name].tobytes() == live[name].tobytes(), name
    # and the strokes did paint: red and blue are both there
    diffuse = live["diffuse"]
    assert ((diffuse[:, 0] > 0.8) & (diffuse[:, 2] < 0.2)).any()
    assert ((diffuse[:, 2] > 0.8) & (diffuse[:, 0] < 0.2)).any()


def save_and_replay(view, tmp_path, mesh=CUBE):
    """Saves the session, replays its recording headless; both surfaces' arrays."""
    key(view, "s", ctrl=True)
    session, replay = tmp_path / "session", tmp_path / "replay"
    r = subprocess.run([BIN, "paint", str(mesh), "--strokes", str(session / "strokes.json"), "-o", str(replay)],
                       capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    return arrays(read_vtp(session / "surface.vtp")), arrays(read_vtp(replay / "surface.vtp"))


def test_a_drag_is_one_stroke_even_when_its_undo_step_does_not_fit(tmp_path):
    view = open_view(tmp_path)
    view.SetUndoBudget(0.001)  # 1 KiB: the drag's undo step does not fit
    drag(view, line(150, 120, 260, 180, 5))
    strokes = json.loads(view.GetRecording())["strokes"]
    assert len(strokes) == 1  # painted once as it was drawn, never in pieces
    assert len(strokes[0]["points"]) > 2
    assert not view.Undo()  # the budget could not keep it
    live, again = save_and_replay(view, tmp_path)
    for name in live:
        assert live[name].tobytes() == again[name].tobytes(), name


def test_coarse_level_edits_replay_to_the_same_bits(tmp_path):
    view = open_view(tmp_path)
    for _ in range(3):
        key(view, "t")  # sculpt
    key(view, "l")
    key(view, "l")      # edit level 2 of 4
    key(view, "bracketright")
    drag(view, line(170, 140, 230, 160, 6))
    # level-of-detail drawing between the strokes leaves the atlas alone
    drawn = lambda: view.GetPicker().GetActor().GetMapper().GetInput()
    full = drawn()
    view.SetLodLevel(3)  # not the automatic choice, which follows frame times
    view.SetMoving(True)
    assert view.GetShownLevel() == 3
    coarse = drawn()
    # a quarter of the quads, over the very same points and arrays
    assert coarse.GetNumberOfCells() * 4 == full.GetNumberOfCells() == view.GetFaceCount()
    assert coarse.GetPoints() is full.GetPoints()
    assert coarse.GetPointData().GetArray("diffuse") is full.GetPointData().GetArray("diffuse")
    # the coarse corners are the texels of level 3: as many as its vertices
    reader = vtk.vtkOBJReader()
    reader.SetFileName(CUBE)
    level3 = meshpaint.vtkCatmullClarkAtlasFilter()
    level3.SetInputConnection(reader.GetOutputPort())
    level3.SetLevel(3)
    level3.Update()
    used = set(vtk_to_numpy(coarse.GetPolys().GetConnectivityArray()).tolist())
    assert len(used) == level3.GetOutput().GetNumberOfPoints()
    assert coarse.GetNumberOfCells() == level3.GetOutput().GetNumberOfCells()
    view.SetMoving(False)
    assert view.GetShownLevel() == 4 and drawn() is full
    drag(view, line(180, 170, 220, 130, 6))
    # A stroke at another level and one at the finest level, both undone:
    # undo gives back the details they replaced, so the next stroke at
    # level 2 keeps them, as the replay (which never sees those) does.
    key(view, "L")      # edit level 3
    drag(view, line(160, 160, 200, 120, 6))
    key(view, "z", ctrl=True)
    key(view, "L")      # level 4, the finest
    drag(view, line(200, 130, 220, 170, 6))
    key(view, "z", ctrl=True)
    key(view, "l")
    key(view, "l")      # level 2 again
    drag(view, line(175, 150, 215, 150, 6))
    strokes = json.loads(view.GetRecording())["strokes"]
    assert [s.get("edit_level") for s in strokes] == [2, 2, 2]
    live, again = save_and_replay(view, tmp_path)
    for name in live:
        assert live[name].tobytes() == again[name].tobytes(), name


def test_strokes_end_off_the_surface(tmp_path):
    view = open_view(tmp_path)
    # From the centre out past the silhouette into the background, and back:
    # the stroke ends where it leaves the surface, so it never comes back.
    drag(view, line(200, 150, 399, 150) + line(399, 160, 220, 160))
    script = json.loads(view.GetRecording())
    (stroke,) = script["strokes"]
    xs = [p[0] for p in stroke["points"]]
    assert xs == sorted(xs)  # only the outward part
    assert max(xs) > 0.8
    # A press on the background paints nothing (it turns the camera).
    drag(view, line(5, 5, 60, 60))
    assert len(json.loads(view.GetRecording())["strokes"]) == 1


def test_keys_change_the_brush_and_the_help_overlay(tmp_path):
    view = open_view(tmp_path)
    assert not view.GetHelpVisible()
    key(view, "h")
    assert view.GetHelpVisible()
    key(view, "F1")
    assert not view.GetHelpVisible()
    key(view, "z", ctrl=True)
    assert view.GetMessage() == "nothing to undo"
    key(view, "c")  # specular
    key(view, "0")  # black swatch
    key(view, "minus")
    key(view, "f")  # gaussian
    key(view, "o")  # over
    drag(view, line(190, 140, 210, 160, 4))
    (stroke,) = json.loads(view.GetRecording())["strokes"]
    assert list(stroke["channels"]) == ["specular"]
    assert all(abs(v - 0.05) < 1e-6 for v in stroke["channels"]["specular"][:3]), stroke["channels"]
    assert abs(stroke["strength"] - 0.9) < 1e-6
    assert stroke["falloff"] == "gaussian" and stroke["op"] == "over"
    # the export key writes the textured model
    key(view, "e", ctrl=True)
    assert (tmp_path / "session" / "model.obj").exists()


def test_failures_raise_meshpaint_errors(tmp_path):
    view = meshpaint.vtkPaintView()
    with pytest.raises(meshpaint.Error, match="no surface to paint"):
        view.Initialize()
    with pytest.raises(meshpaint.Error, match="cannot open '.*no-such.off'"):
        view.LoadMesh(str(tmp_path / "no-such.off"))
    view.SetLevel(2)
    view.LoadMesh(CUBE)
    with pytest.raises(meshpaint.Error, match='stroke 0: "radius"'):
        view.ApplyStrokes('{"strokes": [{"points": [[0.5, 0.5, 1]], "radius": -1}]}')


def test_window_of_a_paint_surface_shares_its_strokes(tmp_path):
    reader = vtk.vtkOBJReader()
    reader.SetFileName(CUBE)
    surface = meshpaint.vtkPaintSurface()
    surface.SetInputConnection(reader.GetOutputPort())
    surface.SetLevel(4)
    surface.Update()
    before = vtk_to_numpy(surface.GetOutput().GetPointData().GetArray("diffuse")).copy()
    view = meshpaint.vtkPaintView()  # the window belongs to whoever makes it
    view.SetPaintSurface(surface)
    assert view.GetLevel() == 4
    # GetView() is the same in one call, a new window each time: the filter keeps none
    other = surface.GetView()
    assert other is not view and other.GetLevel() == 4
    del other
    with pytest.raises(meshpaint.Error, match="nothing to paint on"):
        meshpaint.vtkPaintView().SetPaintSurface(meshpaint.vtkPaintSurface())
    view.SetSize(*SIZE)
    view.OffScreenOn()
    assert view.Initialize(), view.GetLastError()
    drag(view, line(180, 150, 220, 150, 8))
    surface.ViewPainted()
    surface.Update()
    assert surface.GetStrokeCount() == 1
    after = vtk_to_numpy(surface.GetOutput().GetPointData().GetArray("diffuse"))
    assert (after != before).any()
    # the window's stroke is the filter's: its undo takes it back
    surface.Undo()
    surface.Update()
    assert (vtk_to_numpy(surface.GetOutput().GetPointData().GetArray("diffuse")) == before).all()


def test_saving_a_window_on_a_project_continues_the_project(tmp_path):
    project = tmp_path / "cube.meshpaint"
    script = tmp_path / "first.json"
    script.write_text(json.dumps({"strokes": [
        {"tool": "paint", "points": [[0.5, 0.5, 1]], "radius": 0.2, "channels": {"diffuse": [0, 1, 0]}}]}))
    r = subprocess.run([BIN, "paint", CUBE, "--strokes", str(script), "--level", "4", "--save", str(project)],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    surface = meshpaint.vtkPaintSurface()
    surface.LoadProject(str(project))
    view = surface.GetView()
    view.SetSize(*SIZE)
    view.OffScreenOn()
    view.SetSaveDirectory(str(tmp_path / "session"))
    assert view.Initialize(), view.GetLastError()
    drag(view, line(180, 150, 220, 150, 8))
    assert view.Save(), view.GetLastError()
    saved = tmp_path / "session" / "surface.meshpaint"
    assert saved.exists()
    # The saved project holds both strokes: the project's and the window's.
    r = subprocess.run([BIN, "paint", str(saved), "--save", str(tmp_path / "again.meshpaint")],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    again = meshpaint.vtkPaintSurface()
    again.LoadProject(str(tmp_path / "again.meshpaint"))
    assert len(json.loads(again.GetHistoryJSON())["strokes"]) == 2


def test_automatic_level_of_detail_follows_the_frame_budget(tmp_path):
    view = open_view(tmp_path)
    assert view.GetLodLevel() == -1
    for _ in range(3):
        view.GetRenderer().GetActiveCamera().Azimuth(1)
        view.Render()  # frames at rest time the drawing
    view.SetLodFrameRate(0.1)  # 5 s to draw: one level coarser is enough
    assert view.GetLodLevelInUse() == 3
    view.SetLodFrameRate(1000)  # half a millisecond: as coarse as needed
    fast = view.GetLodLevelInUse()
    assert 1 <= fast <= 3
    view.SetMoving(True)
    assert view.GetShownLevel() == fast
    view.SetMoving(False)
    assert view.GetShownLevel() == 4
    view.SetLodLevel(2)  # a level the user sets wins
    assert view.GetLodLevelInUse() == 2
    view.SetLodLevel(0)
    assert view.GetLodLevelInUse() == 4


def test_subsurface_light_key(tmp_path):
    view = open_view(tmp_path)
    view.AntiAliasingOff()  # FXAA's edges are not part of the shading compared here

    def picture():
        grab = vtk.vtkWindowToImageFilter()
        grab.SetInput(view.GetRenderWindow())
        grab.ReadFrontBufferOff()
        grab.Update()
        w, h, _ = grab.GetOutput().GetDimensions()
        pixels = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).astype(int).reshape(h, w, -1)
        return pixels[h // 4:3 * h // 4, w // 4:3 * w // 4]  # the surface, away from the on-screen text

    view.Render()
    plain = picture()
    key(view, "b")
    assert view.GetSubsurfacePasses() == 60 and view.GetMessage() == "subsurface light on"
    view.Render()
    lit = picture()
    assert abs(lit - plain).sum() > 0
    key(view, "b")
    assert view.GetSubsurfacePasses() == 0
    view.Render()
    again = picture()
    print("DIFF", (again != plain).sum(), abs(again - plain).max(), again.shape)
    assert (again == plain).all()


def test_brush_spaces_from_the_window_replay(tmp_path):
    view = open_view(tmp_path)
    key(view, "p")  # tangent
    drag(view, line(150, 120, 200, 140, 6))
    key(view, "p")  # screen: the stroke carries the camera
    key(view, "6")
    drag(view, line(180, 180, 240, 150, 6))
    key(view, "p")  # parameter
    key(view, "3")
    drag(view, [(200, 150)])
    live, again = save_and_replay(view, tmp_path)
    script = json.loads((tmp_path / "session" / "strokes.json").read_text())
    assert [s.get("space") for s in script["strokes"]] == ["tangent", "screen", "parameter"]
    assert "camera" in script["strokes"][1]
    for name in live:
        assert live[name].tobytes() == again[name].tobytes(), name


def inward_cube(tmp_path):
    """The test cube with every face wound the other way (normals inwards)."""
    lines = open(CUBE).read().splitlines()
    out = [" ".join(["f"] + ln.split()[1:][::-1]) if ln.startswith("f ") else ln for ln in lines]
    path = tmp_path / "inward.obj"
    path.write_text("\n".join(out) + "\n")
    return path


@pytest.mark.parametrize("space", ["object", "tangent", "screen"])
def test_drags_paint_on_inward_wound_surfaces(tmp_path, space):
    mesh = inward_cube(tmp_path)
    view = open_view(tmp_path, mesh=mesh)
    assert view.PickObject(200, 150) == 0  # the eye sees the inside of its faces: still the surface
    for _ in range(["object", "tangent", "screen"].index(space)):
        key(view, "p")
    drag(view, line(150, 120, 260, 180, 8))
    (stroke,) = json.loads(view.GetRecording())["strokes"]
    assert stroke.get("space", "object") == space
    assert len(stroke["points"]) >= 5  # it went on with the drag, no silhouette
    live, again = save_and_replay(view, tmp_path, mesh)
    diffuse = live["diffuse"]
    assert ((diffuse[:, 0] > 0.8) & (diffuse[:, 1] < 0.2)).sum() > 10
    for name in live:
        assert live[name].tobytes() == again[name].tobytes(), name


def window_pixels(view):
    view.Render()
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(view.GetRenderWindow())
    grab.ReadFrontBufferOff()
    grab.Update()
    return vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).astype(int)


def test_the_window_shows_labels_in_their_class_colours(tmp_path):
    view = open_view(tmp_path)
    assert view.AddLabelClass(3, "lesion", 0.1, 0.2, 1.0), view.GetLastError()
    assert not view.AddLabelClass(4, "lesion", 1, 1, 1)  # names are unique
    key(view, "t", shift=True)  # the label tool
    key(view, "3")
    drag(view, line(150, 120, 260, 180))
    (stroke,) = json.loads(view.GetRecording())["strokes"]
    assert stroke["tool"] == "label" and stroke["channels"]["label"] == 3

    def blue(rgb):
        return ((rgb[:, 2] > 180) & (rgb[:, 0] < 60) & (rgb[:, 1] < 90)).sum()

    assert blue(window_pixels(view)) == 0  # the materials: labels do not show
    key(view, "v")
    assert view.GetShownChannel() == "label"
    assert blue(window_pixels(view)) > 200
    view.RemoveLabelClass(3)  # without its class the label keeps a colour of its own, not the class's
    assert blue(window_pixels(view)) == 0
    key(view, "V")
    assert view.GetShownChannel() == "diffuse"
    assert view.SetShownChannel("roughness") and not view.SetShownChannel("nothing")
