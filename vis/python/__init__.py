"""meshpaint: paint colour, materials and geometry onto surfaces, from Python.

The classes are meshpaint's VTK classes. VTK's wrapping cannot raise
exceptions from C++, so vtkPaintSurface here is the wrapped class with its
failing calls turned into meshpaint.Error, carrying the same message as the
command line; everything else is the VTK class itself.
"""
from vtkmodules.vtkCommonCore import vtkVersion as _vtkVersion

_BUILT_FOR_VTK = "@VTK_VERSION@"
if _vtkVersion.GetVTKVersion() != _BUILT_FOR_VTK:
    # Loading this module beside another VTK's libraries would crash the process.
    raise ImportError("meshpaint is built for VTK %s, but this Python imports VTK %s: a second VTK is installed "
                      "(pip's vtk, e.g. pulled by pyvista); remove it, see docs/python.md"
                      % (_BUILT_FOR_VTK, _vtkVersion.GetVTKVersion()))

import vtkmodules.vtkCommonExecutionModel  # noqa: E402,F401  (the base classes' module)

from . import meshpaintVis as _wrapped  # noqa: E402
from .meshpaintVis import vtkPaintInteractorStyle  # noqa: E402,F401


class Error(RuntimeError):
    """A failed meshpaint call: bad input, a file problem, or the device."""


def _ignore(caller, event):
    pass


def _quiet(obj):
    """Keeps obj's own error messages (and its executive's) off the console: they
    are raised as Error instead. Only obj is affected, never VTK's global state."""
    if not getattr(obj, "_meshpaint_quiet", False):
        obj.AddObserver("ErrorEvent", _ignore)
        if hasattr(obj, "GetExecutive"):
            obj.GetExecutive().AddObserver("ErrorEvent", _ignore)
        obj._meshpaint_quiet = True


def _shown(value):
    """A number as a person writes it: 0 for 0.0, 1,000,000,000 for 1e9, 0.5."""
    if isinstance(value, float) and value.is_integer() and abs(value) < 1e15:
        value = int(value)
    return "{:,}".format(value) if isinstance(value, int) else "%g" % value


def _refusing_out_of_range(cls):
    """Makes every setter of a ranged property (VTK's clamping setters, which have
    GetXMinValue/GetXMaxValue) raise Error for a value outside the range instead
    of clamping it without a word."""
    for name in dir(cls):
        if not (name.startswith("Get") and name.endswith("MinValue")):
            continue
        prop = name[3:-len("MinValue")]
        base = getattr(cls, "Set" + prop, None)
        if base is None:
            continue

        def checked(self, value, _base=base, _prop=prop):
            low = getattr(self, "Get%sMinValue" % _prop)()
            high = getattr(self, "Get%sMaxValue" % _prop)()
            if not low <= value <= high:
                raise Error("%s must be from %s to %s, not %s" % (_prop, _shown(low), _shown(high), _shown(value)))
            _base(self, value)

        checked.__doc__ = base.__doc__
        setattr(cls, "Set" + prop, checked)
    return cls


@_refusing_out_of_range
class vtkCatmullClarkAtlasFilter(_wrapped.vtkCatmullClarkAtlasFilter):
    __doc__ = _wrapped.vtkCatmullClarkAtlasFilter.__doc__


@_refusing_out_of_range
class vtkSurfacePicker(_wrapped.vtkSurfacePicker):
    __doc__ = _wrapped.vtkSurfacePicker.__doc__


def to_pyvista(data):
    """The output of a meshpaint filter (updated first) or any vtkPolyData as a
    pyvista.PolyData sharing its arrays: pyvista.wrap() of it. Needs PyVista
    installed over Debian's VTK, never with a VTK of its own (docs/python.md)."""
    try:
        import pyvista
    except ImportError as e:
        raise Error("to_pyvista needs PyVista installed without a second VTK: see docs/python.md") from e
    if hasattr(data, "GetOutputDataObject"):
        data.Update()
        data = data.GetOutputDataObject(0)
    return pyvista.wrap(data)


class vtkPaintSurface(_wrapped.vtkPaintSurface):
    __doc__ = _wrapped.vtkPaintSurface.__doc__

    def _check(self, ok):
        if not ok:
            raise Error(self.GetLastError())

    def _set_checked(self, setter, getter, level):
        _quiet(self)
        setter(self, level)
        if getter() != level:
            raise Error(self.GetLastError())

    def SetLevel(self, level):
        """Painting level, 1 to 12; raises Error for any other (nothing is clamped)."""
        self._set_checked(_wrapped.vtkPaintSurface.SetLevel, self.GetLevel, level)

    def SetModelLevel(self, level):
        """Level of ExportModel's model, 0 (automatic) to 12; raises Error for any other."""
        self._set_checked(_wrapped.vtkPaintSurface.SetModelLevel, self.GetModelLevel, level)

    def ApplyStrokes(self, json_text):
        """Checks a stroke script and queues its strokes for the next Update()."""
        self._check(super().ApplyStrokes(json_text))

    def ApplyStroke(self, path):
        """Queues one stroke of the brush set with the setters along a vtkPoints path."""
        self._check(super().ApplyStroke(path))

    def Undo(self):
        """Undoes the last stroke; raises Error when there is nothing to undo."""
        self._check(super().Undo())

    def Redo(self):
        """Redoes the last undone stroke; raises Error when there is none."""
        self._check(super().Redo())

    def SaveProject(self, path):
        """Writes the painted surface and its history as a project (.meshpaint)."""
        self._check(super().SaveProject(str(path)))

    def LoadProject(self, path):
        """Continues from a project: it replaces the input, the level and the history."""
        self._check(super().LoadProject(str(path)))

    def ExportModel(self, directory):
        """Writes surface.vtp, model.obj/.mtl and the PNG maps, as `meshpaint paint -o` does."""
        self._check(super().ExportModel(str(directory)))

    def AddImportArray(self, name, channel):
        """The input's point array `name` as `channel` (--import-array NAME:CHANNEL); Error for an unknown channel."""
        self._check(super().AddImportArray(name, channel))

    def GetChannel(self, name):
        """One channel at every output vertex as a VTK array (numpy: vtk_to_numpy)."""
        array = super().GetChannel(name)
        if array is None:
            raise Error(self.GetLastError())
        return array

    def SetChannel(self, name, values):
        """Writes one channel at every output vertex from a VTK array of that shape."""
        self._check(super().SetChannel(name, values))

    def GetView(self):
        """A new painting window (vtkPaintView, not opened) on this surface, owned by the caller.

        The same as vtkPaintView().SetPaintSurface(self): the filter keeps no
        window. Call ViewPainted() after painting there.
        """
        view = vtkPaintView()
        view.SetPaintSurface(self)
        return view

    def View(self):
        """Opens the painting window on this surface; returns when it is closed."""
        self.GetView().Start()
        self.ViewPainted()

    def Update(self, *args):
        """Paints the queued strokes; raises Error if this update fails."""
        _quiet(self)
        failed = self.GetFailedUpdates()
        super().Update(*args)
        if self.GetFailedUpdates() != failed:
            raise Error(self.GetLastError())


@_refusing_out_of_range
class vtkPaintView(_wrapped.vtkPaintView):
    __doc__ = _wrapped.vtkPaintView.__doc__

    def _check(self, ok):
        if not ok:
            raise Error(self.GetLastError())
        return ok

    def LoadMesh(self, path):
        """Builds the surface from a mesh file; raises Error when it cannot."""
        return self._check(super().LoadMesh(path))

    def SetInputData(self, polydata):
        """Builds the surface from the polygons of a vtkPolyData; raises Error when it cannot."""
        return self._check(super().SetInputData(polydata))

    def AddMesh(self, path):
        """Adds one more object to the scene from a mesh file; raises Error when it cannot."""
        return self._check(super().AddMesh(str(path)))

    def AddInputData(self, polydata):
        """Adds one more object to the scene from the polygons of a vtkPolyData; raises Error when it cannot."""
        return self._check(super().AddInputData(polydata))

    def ApplyStrokes(self, json_text):
        """Applies a stroke script's strokes; raises Error for a bad script."""
        return self._check(super().ApplyStrokes(json_text))

    def SetPaintSurface(self, surface):
        """Paints on a vtkPaintSurface's surface (updated first); raises Error when it has none."""
        return self._check(super().SetPaintSurface(surface))

    def Initialize(self):
        """Creates the window (not started); raises Error without a surface."""
        return self._check(super().Initialize())

    def Save(self):
        """Writes strokes.json and surface.vtp (several objects: NAME/surface.vtp) into SaveDirectory; raises Error when it cannot."""
        return self._check(super().Save())

    def Export(self):
        """Writes the textured model into SaveDirectory; raises Error when it cannot."""
        return self._check(super().Export())
