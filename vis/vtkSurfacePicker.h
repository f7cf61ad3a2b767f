/**
 * @class vtkSurfacePicker
 * @brief The surface point under a pixel, from the hardware item buffer.
 *
 * Capture() renders the view once into vtkHardwareSelector's buffers (the
 * item buffer of both papers: which cell of which prop covers each pixel);
 * every Pick() afterwards is a lookup there plus one ray-cell intersection,
 * so brush samples cost nothing like a render. Capture again whenever the
 * camera or the geometry changes.
 *
 * Picks refer to the surface the actor drew when the buffers were captured,
 * even if the actor has shown another since. Several actors may be picked
 * (a scene of several objects): a pick says which one it hit.
 *
 * A pick reports the world point, the interpolated normal (the point array
 * Normals, else the cell's), the cell, the atlas patch and (u, v) when the
 * surface is a welded meshpaint level (SetPatchResolution), and how
 * squarely the surface faces the viewer, so strokes can end at silhouettes.
 */
#ifndef vtkSurfacePicker_h
#define vtkSurfacePicker_h

#include "meshpaintVisModule.h" // for MESHPAINTVIS_EXPORT

#include <vtkObject.h> // for vtkObject

#include <memory> // for std::unique_ptr

class vtkActor;
class vtkRenderer;

class MESHPAINTVIS_EXPORT vtkSurfacePicker : public vtkObject
{
public:
  static vtkSurfacePicker* New();
  vtkTypeMacro(vtkSurfacePicker, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  //@{
  /// The renderer to pick in, and the actor to pick (its mapper's input
  /// must be a vtkPolyData). Other props hide it but are never picked.
  void SetRenderer(vtkRenderer* renderer);
  vtkRenderer* GetRenderer();
  void SetActor(vtkActor* actor);
  /// The first actor (null without one).
  vtkActor* GetActor();
  //@}

  //@{
  /// Several actors to pick: SetActor() makes `actor` the only one,
  /// AddActor() adds one more, RemoveAllActors() leaves none. Actor k is
  /// the k-th added; GetActorIndex() names the one a pick hit.
  void AddActor(vtkActor* actor);
  void RemoveAllActors();
  int GetNumberOfActors();
  vtkActor* GetActor(int k);
  //@}

  /// Renders the item buffer of the current view. Returns 0 when there is
  /// no renderer with a window, or nothing could be captured.
  int Capture();

  /// Quads per patch side of the picked surface, n = 2^(level - 1) for a
  /// welded level of meshpaint (to_polydata, vtkPaintSurface's output): then
  /// picks also report the patch and (u, v) in it. 0 (default): unknown.
  vtkSetClampMacro(PatchResolution, int, 0, 4096);
  vtkGetMacro(PatchResolution, int);

  /// Drops the captured buffers (a later Pick() captures again).
  void Release();

  /// True between Capture() and Release().
  bool IsCaptured() const;

  /// Looks up display pixel (x, y) (origin bottom left). Returns 1 and sets
  /// the results below when the actor's surface covers it, else 0. Captures
  /// first if needed.
  int Pick(int x, int y);

  //@{
  /// Results of the last successful Pick().
  vtkGetVector3Macro(Point, double);
  vtkGetVector3Macro(Normal, double);
  vtkGetMacro(CellId, vtkIdType);
  /// Which actor was hit (its index among the picked actors).
  vtkGetMacro(ActorIndex, int);
  /// Cosine between the normal and the direction to the camera: 1 facing
  /// the viewer, 0 at a silhouette.
  vtkGetMacro(Facing, double);
  /// The atlas patch and (u, v) in [0, 1]^2 along its texel axes i, j;
  /// -1 and (0, 0) without a PatchResolution.
  vtkGetMacro(Patch, vtkIdType);
  vtkGetMacro(U, double);
  vtkGetMacro(V, double);
  //@}

protected:
  vtkSurfacePicker();
  ~vtkSurfacePicker() override;

  double Point[3] = {0, 0, 0};
  double Normal[3] = {0, 0, 1};
  vtkIdType CellId = -1;
  int ActorIndex = -1;
  double Facing = 0;
  int PatchResolution = 0;
  vtkIdType Patch = -1;
  double U = 0, V = 0;

private:
  vtkSurfacePicker(const vtkSurfacePicker&) = delete;
  void operator=(const vtkSurfacePicker&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
