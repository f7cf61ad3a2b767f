/**
 * @class vtkPaintSurface
 * @brief A polygon mesh painted with stroke scripts on an OpenCL device.
 *
 * Input: any polygonal vtkPolyData. Its polygons become the base mesh
 * through the import steps a mesh file goes through (coincident points
 * welded unless WeldOff(), faces oriented consistently, closed components
 * turned outward; GetImportReport() says what they did), and a 3-component
 * point array `diffuse` (0-1) becomes the diffuse channel.
 * Output: the painted limit surface of the painting level, welded, with
 * point arrays diffuse, specular, roughness, displacement, mask, label and
 * Normals. Strokes are applied in order; every stroke is one undo step.
 * Methods that can fail return 0 and leave the reason in GetLastError(); the
 * Python package raises it as meshpaint.Error.
 *
 * A project (docs/project-format.md) may take the input's place:
 * LoadProject() continues from one, SaveProject() writes one.
 */
#ifndef vtkPaintSurface_h
#define vtkPaintSurface_h

#include "meshpaintVisModule.h" // for MESHPAINTVIS_EXPORT

#include <vtkPolyDataAlgorithm.h> // for vtkPolyDataAlgorithm

#include <memory> // for std::shared_ptr, std::unique_ptr
#include <string> // for std::string

class vtkDataArray;
class vtkPoints;

namespace meshpaint {
class PaintSurface;
struct Project;
}

class MESHPAINTVIS_EXPORT vtkPaintSurface : public vtkPolyDataAlgorithm
{
public:
  static vtkPaintSurface* New();
  vtkTypeMacro(vtkPaintSurface, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  //@{
  /// Painting level, 1 to 12 (default 3). Changing it starts over. A level
  /// outside that range is refused, not clamped: the level stays and
  /// GetLastError() says why (Python raises meshpaint.Error). Once set, a
  /// stroke script's "level" must agree with it.
  void SetLevel(int level);
  vtkGetMacro(Level, int);
  //@}

  //@{
  /// Off (default): every update outputs arrays of its own, a snapshot
  /// that later strokes leave alone. On: where the device's memory is the
  /// host's (PoCL on the CPU, integrated GPUs), the output's points,
  /// normals and channel arrays are the engine's memory itself, which each
  /// update rewrites in place for the patches that changed (and marks
  /// modified) without a copy; DeepCopy() the output to keep a state.
  vtkSetMacro(ShareArrays, bool);
  vtkGetMacro(ShareArrays, bool);
  vtkBooleanMacro(ShareArrays, bool);
  /// Whether the last output shares the engine's memory.
  vtkGetMacro(SharingArrays, bool);
  //@}

  //@{
  /// Whether the input's coincident points are welded (default on), as
  /// `--no-weld` leaves them apart on the command line. Changing it starts over.
  vtkSetMacro(Weld, bool);
  vtkGetMacro(Weld, bool);
  vtkBooleanMacro(Weld, bool);
  //@}

  //@{
  /// `--import-array NAME:CHANNEL`: the input's point array `name` becomes
  /// the channel (diffuse, specular, roughness, displacement, label, mask)
  /// at the next surface built. AddImportArray() returns 0 for an unknown
  /// channel; a missing array or one of the wrong shape fails the Update().
  /// Changing them starts over.
  int AddImportArray(const char* name, const char* channel);
  void RemoveAllImportArrays();
  //@}

  /// What the import steps and repairs did to the input's polygons at the
  /// last surface built from it, one line each as the command line prints
  /// them ("welded 960 coincident vertices (tolerance 1e-05)"); empty when
  /// they changed nothing or the surface is a loaded project's.
  const char* GetImportReport() const { return this->ImportReport.c_str(); }

  //@{
  /// OpenCL device selector (see `meshpaint devices`); empty: default.
  vtkSetStdStringFromCharMacro(Device);
  vtkGetCharFromStdStringMacro(Device);
  //@}

  /// Checks a stroke script (docs/strokes.md) and queues its strokes for
  /// the next Update(). Returns 0, applying nothing, when the script is bad.
  int ApplyStrokes(const char* json);

  //@{
  /// The brush for ApplyStroke(): the stroke-script keys of docs/strokes.md
  /// as setters. Channels set here are painted by every following stroke
  /// until ClearChannels().
  void SetTool(const char* tool);
  void SetRadius(double radius);
  void SetStrength(double strength);
  void SetFalloff(const char* falloff);
  void SetSpacing(double spacing);
  void SetOp(const char* op);
  void SetMirror(const char* axis); ///< "x", "y", "z", or "" for none
  void SetAmount(double amount);
  void SetIterations(int iterations);
  void SetEditLevel(int level); ///< geometry tools: the level edited; 0 for the painting level
  void SetSpace(const char* space); ///< "object", "tangent", "screen", "parameter"
  /// The view of screen-space brushes and patterns (as vtkCamera gives it).
  void SetCamera(double px, double py, double pz, double fx, double fy, double fz, double ux, double uy, double uz,
                 double view_angle);
  void SetBackfaces(const char* policy); ///< "skip" or "paint"
  void SetSide(const char* side);        ///< two-sided surfaces: "auto", "outside", "inside"
  void SetSpray(int drops, double size, int seed); ///< screen space; drops 0: no spray
  void SetDiffuse(double r, double g, double b);
  void SetSpecular(double r, double g, double b);
  void SetRoughness(double roughness);
  void SetDisplacement(double height);
  void SetLabel(int label);
  void SetMask(double mask);
  void ClearChannels();
  //@}

  /// Queues one stroke of the brush above along `path` (world coordinates),
  /// checked exactly as a stroke script is. Returns 0, queuing nothing, when
  /// the brush or path is not valid.
  int ApplyStroke(vtkPoints* path);

  /// The brush above as one stroke-script stroke, without points (JSON).
  const char* GetBrushJSON();

  /// Undoes (redoes) the last stroke; 0 when there is nothing to undo (redo)
  /// or the surface is not painted yet.
  int Undo();
  int Redo();

  //@{
  /// Projects. SaveProject() paints queued strokes first, then writes the
  /// surface, its stroke history (the loaded project's, then this filter's),
  /// the label classes (GetLabelClassName()) and the loaded project's scan. LoadProject() makes the
  /// project the source: the input connection is dropped, the level becomes
  /// the project's, and undo starts afresh. Both return 0 on failure.
  int SaveProject(const char* path);
  int LoadProject(const char* path);
  //@}

  /// The strokes applied so far, undo-aware, after those of a loaded
  /// project: a stroke script (JSON) that replays the painting; empty before
  /// the first update.
  const char* GetHistoryJSON();

  //@{
  /// What `meshpaint paint -o DIR` writes: DIR/surface.vtp, model.obj and
  /// model.mtl at ModelLevel (0: the painting level - 2, at least 1) and the
  /// PNG texture maps. Queued strokes are painted first. 0 on failure.
  int ExportModel(const char* dir);
  /// 0 to 12; another value is refused as SetLevel() refuses one.
  void SetModelLevel(int level);
  vtkGetMacro(ModelLevel, int);
  //@}

  //@{
  /// The label classes, in ascending id: a loaded project's, or, once an
  /// input is painted (Update()), those its field data names (label_ids,
  /// label_names, label_colors, as ExportModel() writes them) and a class
  /// "label ID" for each other id of its label array. SaveProject() and
  /// ExportModel() write them. Out of range: id -1, name "", colour black.
  int GetNumberOfLabelClasses();
  int GetLabelClassId(int i);
  const char* GetLabelClassName(int i);
  void GetLabelClassColor(int i, double rgb[3]);
  //@}

  //@{
  /// One channel at every output vertex: "diffuse", "specular" (3
  /// components), "roughness", "displacement", "mask" (floats), "label"
  /// (ints). GetChannel() returns a new array owned by this filter (valid
  /// until the next GetChannel() of that name), nullptr on failure;
  /// SetChannel() writes one back from an array of that shape (any numeric
  /// type). Setting is not a stroke: no undo step, no history entry.
  vtkDataArray* GetChannel(const char* name);
  int SetChannel(const char* name, vtkDataArray* values);
  //@}

  /// A painting window on this surface (docs/window.md) is a vtkPaintView
  /// given this filter with vtkPaintView::SetPaintSurface(): its strokes go
  /// onto this filter's surface, with undo, redo and recording shared. The
  /// filter keeps no window. After painting there, call ViewPainted() so the
  /// output and StrokeCount follow.
  void ViewPainted();

  /// Strokes applied so far (queued ones not included).
  vtkGetMacro(StrokeCount, int);

#ifndef __VTK_WRAP__
  /// The engine surface painted (null before the first good update), for
  /// windows and other C++ code that paint on it too.
  std::shared_ptr<meshpaint::PaintSurface> GetPaintSurface();
  /// The loaded project, without its layers (null when none): what saves
  /// of this surface carry on.
  const meshpaint::Project* GetProject() const;
#endif

  /// Why the last call or update failed; empty after a good one.
  const char* GetLastError() const { return this->LastError.c_str(); }

  /// Updates that failed so far: the Python package compares it around
  /// Update() to raise only for that update's failure.
  vtkGetMacro(FailedUpdates, int);

protected:
  vtkPaintSurface();
  ~vtkPaintSurface() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  int Level = 3;
  int ModelLevel = 0;
  bool LevelSet = false; // by SetLevel() or a loaded project, not taken from a script
  std::string Device;
  std::string LastError;
  int StrokeCount = 0;
  int FailedUpdates = 0;
  bool ShareArrays = false;
  bool SharingArrays = false;
  bool Weld = true;
  std::string ImportReport;

private:
  vtkPaintSurface(const vtkPaintSurface&) = delete;
  void operator=(const vtkPaintSurface&) = delete;

  int Step(bool back); // Undo (back) or Redo
  //! Paints queued strokes (building the surface if needed) by updating; 0
  //! with LastError set when that fails or there is nothing to paint on.
  int Ready();

  struct Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
