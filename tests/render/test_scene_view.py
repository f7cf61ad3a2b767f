"""The painting window on a scene of two objects in contact, offscreen.

Two flat plates side by side face the camera and touch along x = 0. Strokes
in object, tangent and screen space cross the contact and paint both; a
parameter-space dab paints the object under it only. The recording replays
headless with `meshpaint paint LEFT RIGHT` to the same bits, object by object.
Run by CTest under xvfb-run (see test_render.py).
"""
import json
import subprocess

import numpy as np
import pytest

import meshpaint
from test_view import BIN, SIZE, arrays, drag, key, line, read_vtp


def write_plate(path, x0):
    """A 2 x 2 grid of quads over [x0, x0 + 1] x [-0.5, 0.5] in z = 0, facing +z."""
    with open(path, "w") as f:
        for j in range(3):
            for i in range(3):
                f.write(f"v {x0 + i / 2} {j / 2 - 0.5} 0\n")
        for j in range(2):
            for i in range(2):
                a = j * 3 + i + 1
                f.write(f"f {a} {a + 1} {a + 4} {a + 3}\n")


@pytest.fixture
def plates(tmp_path):
    left, right = tmp_path / "left.obj", tmp_path / "right.obj"
    write_plate(left, -1.0)
    write_plate(right, 0.0)
    return left, right


def open_scene(tmp_path, plates):
    view = meshpaint.vtkPaintView()
    view.SetLevel(3)
    view.SetSize(*SIZE)
    view.OffScreenOn()
    view.SetSaveDirectory(str(tmp_path / "session"))
    view.LoadMesh(str(plates[0]))
    view.AddMesh(str(plates[1]))
    view.Initialize()
    return view


def coloured(diffuse, rgb):
    """How many vertices carry this colour."""
    return int((np.abs(diffuse[:, :3] - np.array(rgb)) < 0.02).all(axis=1).sum())


RED, YELLOW, GREEN, BLUE = (0.85, 0.1, 0.1), (0.95, 0.9, 0.2), (0.2, 0.7, 0.2), (0.15, 0.25, 0.85)  # swatches 1, 3, 4, 6


def test_picking_tells_the_object(tmp_path, plates):
    view = open_scene(tmp_path, plates)
    assert view.GetNumberOfObjects() == 2
    assert [view.GetObjectName(k) for k in range(2)] == ["left", "right"]
    assert view.GetObjectName(2) is None
    assert view.GetPicker().GetNumberOfActors() == 2
    assert view.PickObject(120, 150) == 0
    assert view.PickObject(280, 150) == 1
    assert view.GetPicker().GetActorIndex() == 1
    assert view.PickObject(5, 5) == -1  # the background
    assert view.GetFaceCount() == 2 * 16 * 16  # 16 patches per plate, level 3: 4 x 4 quads per patch
    # level of detail on every object: a quarter of the quads while moving
    drawn = lambda k: view.GetPicker().GetActor(k).GetMapper().GetInput().GetNumberOfCells()
    view.SetLodLevel(2)  # the automatic choice follows frame times, which load on the machine changes
    view.SetMoving(True)
    assert view.GetShownLevel() == 2 and drawn(0) == drawn(1) == 16 * 4
    view.SetMoving(False)
    assert drawn(0) == drawn(1) == 16 * 16


def test_scene_session_paints_across_the_contact_and_replays(tmp_path, plates):
    view = open_scene(tmp_path, plates)
    key(view, "f")
    key(view, "f")                             # constant falloff: the swatch's colour exactly
    for _ in range(3):
        key(view, "bracketright")              # a radius of several texels
    drag(view, line(140, 190, 260, 190, 12))  # object space, red, across the contact
    key(view, "p")                             # tangent
    key(view, "6")                             # blue
    drag(view, line(140, 110, 260, 110, 12))
    key(view, "p")                             # screen
    key(view, "3")                             # yellow
    drag(view, line(160, 150, 240, 150, 8))
    key(view, "p")                             # parameter
    key(view, "4")                             # green
    drag(view, [(100, 150)])                   # one dab, on the left plate
    drag(view, [(150, 100)])
    key(view, "z", ctrl=True)                  # the second dab undone on both
    key(view, "z", ctrl=True)
    key(view, "y", ctrl=True)
    key(view, "s", ctrl=True)
    session = tmp_path / "session"
    script = json.loads((session / "strokes.json").read_text())
    assert script["level"] == 3
    assert [s.get("space", "object") for s in script["strokes"]] == ["object", "tangent", "screen", "parameter"]
    live = {name: arrays(read_vtp(session / name / "surface.vtp")) for name in ("left", "right")}
    assert not (session / "surface.vtp").exists()
    for name in ("left", "right"):
        assert coloured(live[name]["diffuse"], RED) > 0, name
        assert coloured(live[name]["diffuse"], BLUE) > 0, name
        assert coloured(live[name]["diffuse"], YELLOW) > 0, name
    assert coloured(live["left"]["diffuse"], GREEN) > 0
    assert coloured(live["right"]["diffuse"], GREEN) == 0

    replay = tmp_path / "replay"
    r = subprocess.run([BIN, "paint", str(plates[0]), str(plates[1]), "--strokes", str(session / "strokes.json"),
                        "-o", str(replay)], capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    for name in ("left", "right"):
        again = arrays(read_vtp(replay / name / "surface.vtp"))
        assert live[name].keys() == again.keys()
        for array in live[name]:
            assert live[name][array].tobytes() == again[array].tobytes(), (name, array)

    key(view, "e", ctrl=True)
    for name in ("left", "right"):
        assert (session / name / "model.obj").exists(), name


def test_objects_are_added_at_the_scene_level(tmp_path, plates):
    view = meshpaint.vtkPaintView()
    view.SetLevel(2)
    view.LoadMesh(str(plates[0]))
    view.SetLevel(3)  # too late for the scene: the added object joins at level 2
    view.AddMesh(str(plates[1]))
    assert view.GetLevel() == 2 and view.GetNumberOfObjects() == 2
    with pytest.raises(meshpaint.Error, match="cannot open"):
        view.AddMesh(str(tmp_path / "no-such.obj"))
    assert view.GetNumberOfObjects() == 2
    view.LoadMesh(str(plates[1]))  # replaces the scene
    assert view.GetNumberOfObjects() == 1 and view.GetObjectName(0) == "right"
