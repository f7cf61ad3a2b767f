"""Pictures and picking: `meshpaint paint --screenshot` and vtkSurfacePicker.

Run by CTest under xvfb-run with MESHPAINT_BIN, MESHPAINT_SOURCE_DIR and
PYTHONPATH (build/python) set.
"""
import json
import os
import subprocess

import pytest
import vtk  # Debian's python3-vtk9: reads the pictures back
from vtkmodules.util.numpy_support import vtk_to_numpy

import meshpaint

BIN = os.environ["MESHPAINT_BIN"]

# The unit cube; its level-L limit surface is a rounded box centred at 0.5.
with open(os.path.join(os.environ["MESHPAINT_SOURCE_DIR"], "tests", "support", "cube.obj")) as _f:
    CUBE_OBJ = _f.read()
GREY = 0.8  # unpainted diffuse


def write_cube(tmp_path):
    path = tmp_path / "cube.obj"
    path.write_text(CUBE_OBJ)
    return str(path)


def read_png(path):
    """Pixels as rows from the top, columns from the left, RGB."""
    reader = vtk.vtkPNGReader()
    reader.SetFileName(str(path))
    reader.Update()
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)
    return pixels[::-1, :, :3].astype(int)  # VTK images start at the bottom row


def paint_picture(tmp_path, strokes, *extra):
    script = tmp_path / "s.json"
    script.write_text(json.dumps({"strokes": strokes}))
    png = tmp_path / "shot.png"
    r = subprocess.run([BIN, "paint", write_cube(tmp_path), "--strokes", str(script), "--level", "5",
                        "-o", str(tmp_path / "out"), "--screenshot", str(png), "--size", "200x160", *extra],
                       capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    return read_png(png)


def is_red(p):
    return p[0] > 200 and p[1] < 60 and p[2] < 60


def is_grey(p):
    return p[0] > 90 and abs(p[0] - p[1]) < 12 and abs(p[1] - p[2]) < 12


def spot(centre, rgb=(1, 0, 0)):
    return {"tool": "paint", "points": [centre], "radius": 0.15, "falloff": "constant",
            "channels": {"diffuse": list(rgb)}}


def test_painted_spot_is_at_the_centre_of_the_default_view(tmp_path):
    # The default camera looks down -z at the centre: the +z face's centre
    # is the picture's centre, and faces the headlight squarely.
    img = paint_picture(tmp_path, [spot([0.5, 0.5, 1.0])])
    assert img.shape == (160, 200, 3)
    assert is_red(img[80, 100]), img[80, 100]
    # beside the spot: the unpainted grey surface; in the corner: background
    assert is_grey(img[80, 100 + 35]), img[80, 135]
    assert is_grey(img[80, 100 - 35]), img[80, 65]
    assert not is_red(img[80, 135]) and not is_grey(img[2, 2])


def test_camera_turns_the_view(tmp_path):
    # Azimuth 90 brings the camera round to +x: a spot on the +x face is in
    # the centre, one on +z sits at the silhouette, out of the centre.
    strokes = [spot([1.0, 0.5, 0.5], (0, 1, 0)), spot([0.5, 0.5, 1.0])]
    img = paint_picture(tmp_path, strokes, "--camera", "90,0,1.5")
    centre = img[80, 100]
    assert centre[1] > 200 and centre[0] < 60 and centre[2] < 60, centre
    front = paint_picture(tmp_path, strokes)
    assert is_red(front[80, 100])


def render_cube(size=(200, 160)):
    """The cube's painted surface at level 4 in an offscreen window."""
    source = vtk.vtkPolyData()
    points = vtk.vtkPoints()
    polys = vtk.vtkCellArray()
    for line in CUBE_OBJ.splitlines():
        if line.startswith("v "):
            points.InsertNextPoint(*map(float, line.split()[1:]))
        elif line.startswith("f "):
            polys.InsertNextCell(4, [int(i) - 1 for i in line.split()[1:]])
    source.SetPoints(points)
    source.SetPolys(polys)
    surface = meshpaint.vtkPaintSurface()
    surface.SetInputData(source)
    surface.SetLevel(4)
    surface.Update()
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(surface.GetOutputPort())
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    renderer = vtk.vtkRenderer()
    renderer.AddActor(actor)
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.SetSize(*size)
    renderer.ResetCamera()
    window.Render()
    return surface.GetOutput(), actor, renderer, window


def test_pick_at_the_centre_gets_the_centre_of_the_front_face():
    surface, actor, renderer, window = render_cube()
    picker = meshpaint.vtkSurfacePicker()
    picker.SetRenderer(renderer)
    picker.SetActor(actor)
    assert picker.Capture() == 1
    # The ray through the centre pixel runs along the z axis through x = y =
    # 0.5; by symmetry it meets the surface at its highest point.
    zmax = surface.GetBounds()[5]
    pixel_size = 1.0 / 100  # the cube spans well under 200 pixels
    assert picker.Pick(100, 80) == 1
    x, y, z = picker.GetPoint()
    assert abs(x - 0.5) < pixel_size and abs(y - 0.5) < pixel_size
    assert abs(z - zmax) < 1e-3
    assert picker.GetFacing() > 0.99
    nx, ny, nz = picker.GetNormal()
    assert nz > 0.99
    # the reported cell holds the point
    cell = surface.GetCell(picker.GetCellId())
    closest, sub, dist2, pcoords, weights = [0.0] * 3, vtk.reference(0), vtk.reference(0.0), [0.0] * 3, [0.0] * 4
    cell.EvaluatePosition([x, y, z], closest, sub, pcoords, dist2, weights)
    assert dist2.get() < 1e-8


def test_pick_off_the_surface_and_at_the_silhouette():
    surface, actor, renderer, window = render_cube()
    picker = meshpaint.vtkSurfacePicker()
    picker.SetRenderer(renderer)
    picker.SetActor(actor)
    assert picker.Pick(1, 1) == 0  # background (captures on first use)
    assert picker.IsCaptured()
    assert picker.Pick(500, 80) == 0  # outside the window
    # Along the centre row, the last covered pixel is at the silhouette:
    # the surface there turns away from the viewer.
    last = max(x for x in range(100, 200) if picker.Pick(x, 80))
    assert picker.Pick(last, 80) == 1
    assert picker.GetFacing() < 0.5
    # on the +x side, seen in perspective a little in front of its extreme
    xmax = surface.GetBounds()[1]
    assert picker.GetPoint()[0] > xmax - 0.1


def turned_picker(azimuth, elevation):
    """The cube rendered with the camera turned, and a picker on it."""
    surface, actor, renderer, window = render_cube()
    renderer.GetActiveCamera().Azimuth(azimuth)
    renderer.GetActiveCamera().Elevation(elevation)
    renderer.ResetCameraClippingRange()
    window.Render()
    picker = meshpaint.vtkSurfacePicker()
    picker.SetRenderer(renderer)
    picker.SetActor(actor)
    picker.scene = (actor, window)  # nothing else keeps the window alive
    return surface, renderer, picker


def test_pick_agrees_with_the_screen_position_of_a_known_point():
    surface, renderer, picker = turned_picker(30, 20)
    picker.Capture()
    # The vertex at the centre of the +z face, projected to the screen and
    # picked there, comes back to within a pixel's width.
    zmax = surface.GetBounds()[5]
    target = (0.5, 0.5, zmax)
    renderer.SetWorldPoint(*target, 1.0)
    renderer.WorldToDisplay()
    dx, dy, _ = renderer.GetDisplayPoint()
    assert picker.Pick(int(dx), int(dy)) == 1
    p = picker.GetPoint()
    assert sum((a - b) ** 2 for a, b in zip(p, target)) ** 0.5 < 0.02


def test_pick_reports_the_patch_and_its_texel_coordinates():
    surface, renderer, picker = turned_picker(25, 15)
    assert picker.Pick(90, 90) == 1 and picker.GetPatch() == -1  # no resolution given
    n = 8  # level 4: 2^3 quads per patch side
    picker.SetPatchResolution(n)
    seen = set()
    for x, y in [(90, 90), (110, 70), (70, 95), (100, 100)]:
        assert picker.Pick(x, y) == 1
        patch, u, v = picker.GetPatch(), picker.GetU(), picker.GetV()
        assert 0 <= patch < surface.GetNumberOfCells() // (n * n) and 0 <= u <= 1 and 0 <= v <= 1
        seen.add(patch)
        # (patch, u, v) leads back to the picked point on the welded grid
        i, j = min(int(u * n), n - 1), min(int(v * n), n - 1)
        cell = surface.GetCell(patch * n * n + j * n + i)
        point, weights = [0.0] * 3, [0.0] * 4
        cell.EvaluateLocation(vtk.reference(0), [u * n - i, v * n - j, 0.0], point, weights)
        assert sum((a - b) ** 2 for a, b in zip(point, picker.GetPoint())) ** 0.5 < 1e-4
    assert len(seen) > 1


def test_subsurface_light_softens_the_shading(tmp_path):
    # A cube seen over a corner: its three faces differ in light. Light
    # diffused in atlas space bleeds across the edges, so the faces differ
    # less; the background is untouched.
    import numpy as np
    plain = paint_picture(tmp_path, [], "--camera", "40,30,1")
    soft = paint_picture(tmp_path, [], "--camera", "40,30,1", "--subsurface", "200")
    background = plain[0, 0]
    on_cube = np.any(plain != background, axis=2) & np.any(soft != background, axis=2)
    assert on_cube.sum() > 2000
    assert (soft[0, 0] == background).all()
    grey = lambda img: img[on_cube].mean(axis=1)
    assert grey(soft).std() < 0.8 * grey(plain).std(), (grey(soft).std(), grey(plain).std())


def label_spot(centre, label):
    return {"tool": "label", "points": [centre], "radius": 0.15, "falloff": "constant", "channels": {"label": label}}


def test_show_label_draws_classes_in_their_colours(tmp_path):
    labels = tmp_path / "labels.json"
    labels.write_text(json.dumps([{"id": 3, "name": "lesion", "colour": [0.1, 0.2, 1.0]}]))
    strokes = [spot([0.5, 0.5, 1.0]), label_spot([0.5, 0.5, 1.0], 3)]
    shown = paint_picture(tmp_path, strokes, "--show", "label", "--labels", str(labels))
    # the class's blue at the centre; around it the surface in its material (grey)
    c = shown[80, 100]
    assert c[2] > 180 and c[0] < 60 and c[1] < 90, c
    assert is_grey(shown[80, 135]), shown[80, 135]
    # the default shows the diffuse paint, not the label
    assert is_red(paint_picture(tmp_path, strokes)[80, 100])
    # a label without a class still shows, in a colour of its own
    other = paint_picture(tmp_path, [label_spot([0.5, 0.5, 1.0], 4)], "--show", "label")
    assert not is_grey(other[80, 100]) and is_grey(other[80, 135]), other[80, 100]


def test_show_scalar_channels_through_a_colour_map(tmp_path):
    strokes = [{"tool": "paint", "points": [[0.5, 0.5, 1.0]], "radius": 0.15, "falloff": "constant",
                "channels": {"roughness": 1.0, "mask": 1.0}}]
    for channel in ("roughness", "mask"):
        img = paint_picture(tmp_path, strokes, "--show", channel)
        centre, beside = img[80, 100], img[80, 135]
        assert centre[0] > centre[2] and beside[2] > beside[0], (channel, centre, beside)  # yellow over dark blue-green


def test_show_needs_a_screenshot_and_a_known_channel(tmp_path):
    script = tmp_path / "s.json"
    script.write_text(json.dumps({"strokes": []}))
    base = [BIN, "paint", write_cube(tmp_path), "--strokes", str(script), "-o", str(tmp_path / "o")]
    for extra in (["--show", "label"], ["--screenshot", str(tmp_path / "a.png"), "--show", "labels"]):
        r = subprocess.run(base + extra, capture_output=True, text=True, timeout=600)
        assert r.returncode == 2 and len(r.stderr.splitlines()) == 1, r.stderr


@pytest.mark.parametrize("display", [None, ":97"])
def test_without_a_display_view_and_screenshot_say_so(tmp_path, display):
    env = dict(os.environ)
    env.pop("DISPLAY", None)
    if display:
        env["DISPLAY"] = display  # a display nobody serves
    script = tmp_path / "s.json"
    script.write_text(json.dumps({"strokes": []}))
    cube = write_cube(tmp_path)
    # Wound inwards and closed: its import turns it and says so, which view
    # must not get to before it finds no display.
    inward = tmp_path / "inward.obj"
    inward.write_text("\n".join(" ".join(["f"] + l.split()[1:][::-1]) if l.startswith("f ") else l
                                 for l in CUBE_OBJ.splitlines()) + "\n")
    labels = tmp_path / "labels.json"
    labels.write_text(json.dumps([{"id": 1, "name": "nose", "colour": [0.1, 0.3, 1.0]}]))
    for args in (["paint", cube, "--strokes", str(script), "-o", str(tmp_path / "o"),
                  "--screenshot", str(tmp_path / "a.png")], ["view", cube], ["view", str(inward)],
                 ["view", str(inward), "--labels", str(labels)],
                 ["bench", "view", "--steps", "1"], ["bench", "view", "--studio", "--steps", "1"]):
        r = subprocess.run([BIN, *args], capture_output=True, text=True, timeout=600, env=env)
        assert r.returncode == 3, (args, r.returncode, r.stderr)
        (line,) = r.stderr.splitlines()
        assert "xvfb-run" in line and "DISPLAY" in line
    assert not (tmp_path / "a.png").exists()
    # Bad flags are found before the mesh is read, display or not.
    for flags in (["--level", "0"], ["--lod", "9"], ["--labels", str(tmp_path / "none.json")]):
        r = subprocess.run([BIN, "view", str(inward), *flags], capture_output=True, text=True, timeout=600, env=env)
        assert r.returncode == 2, (flags, r.returncode, r.stderr)
        (line,) = r.stderr.splitlines()
        assert "turned" not in line, line
