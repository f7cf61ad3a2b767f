/**
 * @class vtkPaintSurface
 * @brief A polygon mesh painted with stroke scripts on an OpenCL device.
 *
 * Input: any polygonal vtkPolyData (its polygons are the base mesh).
 * Output: the painted limit surface of the painting level, welded, with
 * point arrays diffuse, specular, roughness, displacement, mask, label and
 * Normals. Strokes are applied in order; every stroke is one undo step.
 * Methods that can fail return 0 and leave the reason in GetLastError(); the
 * Python package raises it as meshpaint.Error.
 */
#ifndef vtkPaintSurface_h
#define vtkPaintSurface_h

#include "meshpaintVisModule.h" // for MESHPAINTVIS_EXPORT

#include <vtkPolyDataAlgorithm.h> // for vtkPolyDataAlgorithm

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkPoints;

class MESHPAINTVIS_EXPORT vtkPaintSurface : public vtkPolyDataAlgorithm
{
public:
  static vtkPaintSurface* New();
  vtkTypeMacro(vtkPaintSurface, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  //@{
  /// Painting level, 1 to 12 (default 3). Changing it starts over.
  vtkSetClampMacro(Level, int, 1, 12);
  vtkGetMacro(Level, int);
  //@}

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

  /// Strokes applied so far (queued ones not included).
  vtkGetMacro(StrokeCount, int);

  /// Why the last call or update failed; empty after a good one.
  const char* GetLastError() const { return this->LastError.c_str(); }

  /// Updates that failed so far: the Python package compares it around
  /// Update() to raise only for that update's failure.
  vtkGetMacro(FailedUpdates, int);

protected:
  vtkPaintSurface();
  ~vtkPaintSurface() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Level = 3;
  std::string Device;
  std::string LastError;
  int StrokeCount = 0;
  int FailedUpdates = 0;

private:
  vtkPaintSurface(const vtkPaintSurface&) = delete;
  void operator=(const vtkPaintSurface&) = delete;

  int Step(bool back); // Undo (back) or Redo

  struct Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
