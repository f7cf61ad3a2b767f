"""meshpaint: paint colour, materials and geometry onto surfaces, from Python.

The classes are meshpaint's VTK classes. VTK's wrapping cannot raise
exceptions from C++, so vtkPaintSurface here is the wrapped class with its
failing calls turned into meshpaint.Error, carrying the same message as the
command line; everything else is the VTK class itself.
"""
import vtkmodules.vtkCommonExecutionModel  # noqa: F401  (the base classes' module)

from . import meshpaintVis as _wrapped
from .meshpaintVis import vtkCatmullClarkAtlasFilter, vtkPaintInteractorStyle, vtkSurfacePicker  # noqa: F401


class Error(RuntimeError):
    """A failed meshpaint call: bad input, a file problem, or the device."""


class vtkPaintSurface(_wrapped.vtkPaintSurface):
    __doc__ = _wrapped.vtkPaintSurface.__doc__

    def _check(self, ok):
        if not ok:
            raise Error(self.GetLastError())

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
        self.GlobalWarningDisplayOff()
        failed = self.GetFailedUpdates()
        super().Update(*args)
        if self.GetFailedUpdates() != failed:
            raise Error(self.GetLastError())


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
