#include "vtkPaintView.h"

#include "BrushSettings.h"           // for meshpaint::BrushSettings
#include "LevelOfDetail.h"           // for meshpaint::coarser_quads
#include "SharedArrays.h"            // for meshpaint::share_arrays, refresh_shared_arrays
#include "CallGuard.h"               // for meshpaint::guarded
#include "RasterIO.h"                // for meshpaint::load_stroke_rasters
#include "SurfaceConversion.h"       // for meshpaint::to_polydata, to_base_mesh, write_vtp, write_texture_maps
#include "SurfaceRendering.h"        // for meshpaint::show_materials, set_camera
#include "vtkPaintInteractorStyle.h" // for vtkPaintInteractorStyle
#include "vtkSurfacePicker.h"        // for vtkSurfacePicker

#include "core/atomic_file.h"    // for meshpaint::write_atomically
#include "core/errors.h"         // for meshpaint::IOError
#include "paint/model_export.h"  // for meshpaint::build_export, write_obj_model
#include "paint/paint_scene.h"   // for meshpaint::PaintScene
#include "paint/paint_surface.h" // for meshpaint::PaintSurface
#include "project/project.h"         // for meshpaint::Project, save_project
#include "project/project_surface.h" // for meshpaint::capture_surface, continued_history

#include <vtkActor.h>                   // for vtkActor
#include <vtkBoundingBox.h>             // for vtkBoundingBox
#include <vtkFloatArray.h>              // for vtkFloatArray
#include <vtkPointData.h>               // for vtkPointData
#include <vtkCamera.h>                  // for vtkCamera
#include <vtkCommand.h>                 // for vtkCommand
#include <vtkMapper.h>                  // for vtkMapper
#include <vtkNew.h>                     // for vtkNew
#include <vtkObjectFactory.h>           // for vtkStandardNewMacro
#include <vtkPolyData.h>                // for vtkPolyData
#include <vtkPolyDataMapper.h>          // for vtkPolyDataMapper
#include <vtkProperty.h>                // for vtkProperty
#include <vtkRegularPolygonSource.h>    // for vtkRegularPolygonSource
#include <vtkRenderWindow.h>            // for vtkRenderWindow
#include <vtkRenderWindowInteractor.h>  // for vtkRenderWindowInteractor
#include <vtkRenderer.h>                // for vtkRenderer
#include <vtkSmartPointer.h>            // for vtkSmartPointer
#include <vtkTextActor.h>               // for vtkTextActor
#include <vtkTextProperty.h>            // for vtkTextProperty

#include <algorithm>  // for std::min, std::max
#include <array>      // for std::array
#include <chrono>     // for std::chrono::steady_clock
#include <cmath>      // for std::sqrt
#include <cstdint>    // for std::uint64_t
#include <filesystem> // for std::filesystem
#include <fstream>    // for std::ofstream

vtkStandardNewMacro(vtkPaintView);

// One object of the scene as drawn: its painted surface at the painting
// level, brought up to date when next shown after a change, its coarser
// tessellation for the level of detail (made once per level, sharing the
// arrays), and its actor, which draws `shown`.
struct vtkPaintView::Drawing
{
  vtkSmartPointer<vtkPolyData> full, coarse, shown;
  bool full_stale = true;
  std::uint64_t full_count = 0; // the surface's change_count() that `full` shows
  bool shared = false;          // `full` draws from the engine's display arrays
  std::vector<std::uint64_t> seen; // their versions `full` was last marked for
  int coarse_level = 0;
  vtkNew<vtkActor> actor;
};

struct vtkPaintView::Internals
{
  meshpaint::PaintScene scene;
  std::vector<std::unique_ptr<Drawing>> drawings; // one per object, in the scene's order
  std::unique_ptr<meshpaint::Project> project; // where the first object came from, if from a project
  std::unique_ptr<meshpaint::BrushSettings> brush;
  bool lit = false; // drawn with the subsurface light
  bool moving = false; // the camera turns or a stroke is drawn
  int shown_level = 0;
  // Least time per drawn quad of a frame at rest, in ms (0: none timed yet),
  // from which the automatic level of detail is chosen.
  double ms_per_face = 0;
  std::array<int, 2> timed_size{}; // the window size it was timed at
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkRenderWindowInteractor> interactor;
  vtkNew<vtkPaintInteractorStyle> style;
  vtkNew<vtkSurfacePicker> picker;
  vtkNew<vtkRegularPolygonSource> cursor_shape;
  vtkNew<vtkActor> cursor;
  vtkNew<vtkTextActor> status;
  vtkNew<vtkTextActor> help;
  bool initialized = false;
  // The item buffer holds for one view: camera pose and window size (the
  // camera's modification time also moves with every clipping-range reset).
  std::array<double, 13> captured_view{};
  // The running stroke: its path, and the pieces painted for the eye.
  bool painting = false;
  bool ended = false; // reached a silhouette or left the surface
  std::vector<meshpaint::Vec3> path;
  int pieces = 0;
  std::string recording;
};

vtkPaintView::vtkPaintView() : Impl(new Internals) {}

vtkPaintView::~vtkPaintView() = default;

void vtkPaintView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Level: " << this->Level << "\n";
  os << indent << "Device: " << (this->Device.empty() ? "(default)" : this->Device) << "\n";
  os << indent << "Storage: " << (this->Storage.empty() ? "(default)" : this->Storage) << "\n";
  os << indent << "Size: " << this->Size[0] << " x " << this->Size[1] << "\n";
  os << indent << "OffScreen: " << this->OffScreen << "\n";
  os << indent << "SaveDirectory: " << this->SaveDirectory << "\n";
  os << indent << "Objects: " << this->Impl->scene.size() << "\n";
  os << indent << "SilhouetteCosine: " << this->SilhouetteCosine << "\n";
}

int vtkPaintView::LoadMesh(const char* path)
{
  return this->LoadObject(path, false);
}

int vtkPaintView::AddMesh(const char* path)
{
  return this->LoadObject(path, true);
}

int vtkPaintView::SetInputData(vtkPolyData* polygons)
{
  return this->InputObject(polygons, false);
}

int vtkPaintView::AddInputData(vtkPolyData* polygons)
{
  return this->InputObject(polygons, true);
}

int vtkPaintView::SetBaseMesh(const meshpaint::BaseMesh& mesh)
{
  return this->MeshObject(mesh, false);
}

int vtkPaintView::AddBaseMesh(const meshpaint::BaseMesh& mesh)
{
  return this->MeshObject(mesh, true);
}

int vtkPaintView::LoadObject(const char* path, bool add)
{
  meshpaint::BaseMesh mesh;
  if (!meshpaint::guarded(this->LastError, [&] { mesh = meshpaint::load_mesh(path ? path : ""); }))
    return 0;
  return this->MeshObject(mesh, add);
}

int vtkPaintView::InputObject(vtkPolyData* polygons, bool add)
{
  meshpaint::BaseMesh mesh;
  if (!meshpaint::guarded(this->LastError, [&] {
        if (!polygons)
          throw meshpaint::InputError("no input polygons");
        mesh = meshpaint::to_base_mesh(polygons, "input");
      }))
    return 0;
  return this->MeshObject(mesh, add);
}

int vtkPaintView::MeshObject(const meshpaint::BaseMesh& mesh, bool add)
{
  return meshpaint::guarded(this->LastError, [&] {
    Internals& in = *this->Impl;
    // A scene paints at one level: the objects already there set it.
    const int level = add && !in.scene.empty() ? in.scene.surface(0).level() : this->Level;
    auto runtime = meshpaint::Runtime::open(this->Device);
    const meshpaint::AtlasStorage storage = this->Storage.empty() ? meshpaint::default_storage(runtime->info())
                                                                  : meshpaint::parse_storage(this->Storage);
    auto surface = std::make_shared<meshpaint::PaintSurface>(runtime, mesh, level, storage);
    if (!add)
      this->RemoveObjects();
    this->AddObject(std::move(surface), mesh.name);
  });
}

void vtkPaintView::SetProject(const meshpaint::Project& project)
{
  this->Impl->project = std::make_unique<meshpaint::Project>(project);
  // The layers live in the surface; a save takes them from there.
  this->Impl->project->positions.clear();
  this->Impl->project->channels = meshpaint::PaintChannels();
}

void vtkPaintView::SetSurface(std::shared_ptr<meshpaint::PaintSurface> surface, const std::string& name)
{
  this->RemoveObjects();
  this->AddObject(std::move(surface), name);
}

void vtkPaintView::AddSurface(std::shared_ptr<meshpaint::PaintSurface> surface, const std::string& name)
{
  this->AddObject(std::move(surface), name);
}

void vtkPaintView::RemoveObjects()
{
  Internals& in = *this->Impl;
  if (in.initialized) {
    for (const auto& d : in.drawings)
      in.renderer->RemoveActor(d->actor);
    in.picker->RemoveAllActors();
  }
  in.drawings.clear();
  in.scene.clear();
  in.project.reset();
}

void vtkPaintView::AddObject(std::shared_ptr<meshpaint::PaintSurface> surface, const std::string& name)
{
  Internals& in = *this->Impl;
  in.scene.add(std::move(surface), name); // checks the level
  this->Level = in.scene.surface(0).level();
  in.drawings.push_back(std::make_unique<Drawing>());
  in.ms_per_face = 0; // other objects draw at another rate
  in.moving = false;
  in.shown_level = this->Level;
  Drawing& d = *in.drawings.back();
  d.shown = this->Surface(in.drawings.size() - 1, this->Level);
  // The brush is sized to the whole scene.
  vtkBoundingBox box;
  for (const auto& other : in.drawings)
    box.AddBounds(other->full->GetBounds());
  in.brush = std::make_unique<meshpaint::BrushSettings>(box.GetDiagonalLength(), this->Level);
  if (in.initialized) {
    this->ShowObject(d);
    in.picker->SetPatchResolution(1 << (this->Level - 1));
  }
  this->Modified();
}

void vtkPaintView::ShowObject(Drawing& d)
{
  Internals& in = *this->Impl;
  meshpaint::show_materials(d.actor, d.shown);
  in.renderer->AddActor(d.actor);
  in.picker->AddActor(d.actor);
}

bool vtkPaintView::Shows(const std::shared_ptr<meshpaint::PaintSurface>& surface) const
{
  const meshpaint::PaintScene& scene = this->Impl->scene;
  for (std::size_t k = 0; k < scene.size(); ++k)
    if (scene.shared(k) == surface)
      return true;
  return false;
}

int vtkPaintView::GetNumberOfObjects() { return int(this->Impl->scene.size()); }

const char* vtkPaintView::GetObjectName(int k)
{
  const meshpaint::PaintScene& scene = this->Impl->scene;
  return k >= 0 && std::size_t(k) < scene.size() ? scene.name(std::size_t(k)).c_str() : nullptr;
}

int vtkPaintView::ApplyStrokes(const char* json)
{
  meshpaint::StrokeScript script;
  if (!meshpaint::guarded(this->LastError, [&] {
        script = meshpaint::parse_stroke_script(json ? json : "");
        meshpaint::load_stroke_rasters(script);
      }))
    return 0;
  return this->ApplyScript(script);
}

int vtkPaintView::ApplyScript(const meshpaint::StrokeScript& script)
{
  Internals& in = *this->Impl;
  const int ok = meshpaint::guarded(this->LastError, [&] {
    if (in.scene.empty())
      throw meshpaint::InputError("no surface to paint: load a mesh first");
    for (const meshpaint::Stroke& s : script.strokes)
      in.scene.apply(s);
  });
  const std::string error = this->LastError; // showing what was painted must not hide why it stopped
  this->Refresh(true);
  if (!ok)
    this->LastError = error;
  return ok;
}

int vtkPaintView::Initialize()
{
  Internals& in = *this->Impl;
  if (in.scene.empty()) {
    this->LastError = "no surface to paint: load a mesh first";
    return 0;
  }
  if (in.initialized)
    return 1;
  in.picker->RemoveAllActors();
  for (const auto& d : in.drawings)
    this->ShowObject(*d);
  in.renderer->SetBackground(0.12, 0.12, 0.14);

  in.cursor_shape->SetNumberOfSides(40);
  in.cursor_shape->GeneratePolygonOff();
  vtkNew<vtkPolyDataMapper> cursor_mapper;
  cursor_mapper->SetInputConnection(in.cursor_shape->GetOutputPort());
  in.cursor->SetMapper(cursor_mapper);
  in.cursor->GetProperty()->SetColor(1.0, 0.85, 0.2);
  in.cursor->GetProperty()->LightingOff();
  in.cursor->GetProperty()->SetLineWidth(2.0);
  in.cursor->PickableOff(); // the item buffer must see the surface through it
  in.cursor->VisibilityOff();
  in.renderer->AddActor(in.cursor);

  in.status->GetTextProperty()->SetFontSize(15);
  in.status->GetTextProperty()->SetColor(0.95, 0.95, 0.95);
  in.status->SetPosition(10, 10);
  in.renderer->AddActor2D(in.status);
  in.help->GetTextProperty()->SetFontSize(14);
  in.help->GetTextProperty()->SetFontFamilyToCourier();
  in.help->GetTextProperty()->SetColor(1.0, 1.0, 0.8);
  in.help->GetTextProperty()->SetVerticalJustificationToTop();
  in.help->SetInput((meshpaint::BrushSettings::key_help() +
                     "\nleft-drag    paint (off the surface, or with Alt: turn the camera)\n"
                     "middle-drag  pan;  right-drag, wheel: zoom\n"
                     "Ctrl+Z / Ctrl+Y  undo / redo\n"
                     "Ctrl+S       save strokes.json and surface.vtp\n"
                     "Ctrl+E       export model.obj with texture maps\n"
                     "r            reset the camera\n"
                     "b            subsurface light at rest (on / off)\n"
                     "h, F1        this help;  q, Escape: quit")
                      .c_str());
  in.help->VisibilityOff();
  in.renderer->AddActor2D(in.help);

  in.window->AddRenderer(in.renderer);
  in.window->SetSize(this->Size);
  // Multisampling triples the cost of a frame on a software rasterizer;
  // FXAA smooths the edges of frames at rest instead (see Show()).
  in.window->SetMultiSamples(0);
  in.renderer->SetUseFXAA(this->AntiAliasing);
  in.window->SetOffScreenRendering(this->OffScreen ? 1 : 0);
  in.window->SetWindowName("meshpaint");
  in.interactor->SetRenderWindow(in.window);
  in.style->SetView(this);
  in.interactor->SetInteractorStyle(in.style);
  in.style->AddObserver(vtkCommand::StartInteractionEvent, this, &vtkPaintView::OnCameraInteraction);
  in.style->AddObserver(vtkCommand::EndInteractionEvent, this, &vtkPaintView::OnCameraInteraction);
  in.picker->SetRenderer(in.renderer);
  in.picker->SetPatchResolution(1 << (this->Level - 1)); // captures happen at rest: the full level
  meshpaint::set_camera(in.renderer, meshpaint::CameraView());
  in.interactor->Initialize();
  in.initialized = true;
  this->UpdateText();
  this->Render();
  return 1;
}

void vtkPaintView::Start()
{
  if (this->Initialize())
    this->Impl->interactor->Start();
}

void vtkPaintView::Render()
{
  Internals& in = *this->Impl;
  if (!in.initialized)
    return;
  const auto start = std::chrono::steady_clock::now();
  in.window->Render();
  if (in.shown_level != this->Level)
    return;
  // The least time seen is the drawing itself, without uploads after edits
  // or a busy host; a new window size starts afresh (llvmpipe's cost is
  // much per pixel).
  const std::chrono::duration<double, std::milli> took = std::chrono::steady_clock::now() - start;
  const int* size = in.window->GetSize();
  if (size[0] != in.timed_size[0] || size[1] != in.timed_size[1]) {
    in.ms_per_face = 0;
    in.timed_size = {size[0], size[1]};
  }
  const double per_face = took.count() / double(std::max<vtkIdType>(1, this->GetFaceCount()));
  if (in.ms_per_face == 0 || per_face < in.ms_per_face)
    in.ms_per_face = per_face;
}

vtkRenderWindow* vtkPaintView::GetRenderWindow() { return this->Impl->window; }
vtkRenderer* vtkPaintView::GetRenderer() { return this->Impl->renderer; }
vtkRenderWindowInteractor* vtkPaintView::GetInteractor() { return this->Impl->interactor; }
vtkSurfacePicker* vtkPaintView::GetPicker() { return this->Impl->picker; }

bool vtkPaintView::PickFacing(int x, int y, double point[3], double normal[3])
{
  Internals& in = *this->Impl;
  if (!in.initialized)
    return false;
  vtkCamera* camera = in.renderer->GetActiveCamera();
  const int* size = in.window->GetSize();
  std::array<double, 13> view;
  camera->GetPosition(&view[0]);
  camera->GetFocalPoint(&view[3]);
  camera->GetViewUp(&view[6]);
  view[9] = camera->GetViewAngle();
  view[10] = camera->GetParallelProjection() ? camera->GetParallelScale() : 0.0;
  view[11] = size[0];
  view[12] = size[1];
  if (!in.picker->IsCaptured() || view != in.captured_view) {
    in.picker->Capture();
    in.captured_view = view;
  }
  if (!in.picker->Pick(x, y) || in.picker->GetFacing() < this->SilhouetteCosine)
    return false;
  in.picker->GetPoint(point);
  in.picker->GetNormal(normal);
  return true;
}

int vtkPaintView::BeginStroke(int x, int y)
{
  Internals& in = *this->Impl;
  double p[3], n[3];
  if (in.painting || !this->PickFacing(x, y, p, n))
    return 0;
  for (std::size_t o = 0; o < in.scene.size(); ++o)
    in.scene.surface(o).undo_log().set_budget(std::size_t(this->UndoBudget * 1048576.0));
  in.painting = true;
  in.ended = false;
  in.path = {meshpaint::Vec3{float(p[0]), float(p[1]), float(p[2])}};
  in.pieces = 0;
  in.moving = true;
  { // screen-space strokes carry the view they are drawn in
    vtkCamera* c = in.renderer->GetActiveCamera();
    meshpaint::Camera camera;
    for (int k = 0; k < 3; ++k) {
      camera.position[k] = float(c->GetPosition()[k]);
      camera.focal_point[k] = float(c->GetFocalPoint()[k]);
      camera.view_up[k] = float(c->GetViewUp()[k]);
    }
    camera.view_angle = float(c->GetViewAngle());
    in.brush->set_camera(camera);
  }
  this->PaintPiece(true);
  return 1;
}

int vtkPaintView::ContinueStroke(int x, int y)
{
  Internals& in = *this->Impl;
  if (!in.painting || in.ended)
    return 0;
  double p[3], n[3];
  if (!this->PickFacing(x, y, p, n)) {
    in.ended = true; // a silhouette, or no surface under the brush
    return 0;
  }
  const meshpaint::Vec3 q{float(p[0]), float(p[1]), float(p[2])};
  const meshpaint::Vec3& last = in.path.back();
  const double d = std::sqrt(double((q[0] - last[0]) * (q[0] - last[0]) + (q[1] - last[1]) * (q[1] - last[1]) +
                                    (q[2] - last[2]) * (q[2] - last[2])));
  // Points closer than half a dab spacing add nothing but cost.
  if (d < 0.5 * in.brush->spacing() * in.brush->radius())
    return 1;
  in.path.push_back(q);
  this->PlaceCursor(x, y);
  this->PaintPiece(false); // renders
  return 1;
}

void vtkPaintView::PaintPiece(bool first)
{
  Internals& in = *this->Impl;
  const std::vector<meshpaint::Vec3> piece =
    first ? in.path : std::vector<meshpaint::Vec3>(in.path.end() - 2, in.path.end());
  if (meshpaint::guarded(this->LastError, [&] { in.scene.apply(in.brush->stroke(piece)); }))
    ++in.pieces;
  this->Refresh(false);
}

int vtkPaintView::EndStroke()
{
  Internals& in = *this->Impl;
  if (!in.painting)
    return 0;
  in.painting = false;
  in.moving = false;
  // The pieces were for the eye: the stroke is the whole path, applied once.
  // Undo gives back the surface and its multiresolution details bit for
  // bit, so this is what a replay of the recording does.
  std::string note;
  const int ok = meshpaint::guarded(this->LastError, [&] {
    int undone = 0;
    while (undone < in.pieces && in.scene.undo())
      ++undone;
    if (undone == in.pieces) {
      in.scene.apply(in.brush->stroke(in.path));
    } else {
      // The undo budget forgot a piece already (one step larger than the
      // whole budget): the pieces stay strokes of their own, as recorded.
      for (; undone > 0; --undone)
        in.scene.redo();
      note = "undo budget too small for this stroke: kept as " + std::to_string(in.pieces) + " strokes";
    }
    in.pieces = 0;
  });
  this->Message = ok ? note : this->LastError;
  this->Refresh(true);
  return ok;
}

bool vtkPaintView::IsPainting() const { return this->Impl->painting; }

void vtkPaintView::MoveCursor(int x, int y)
{
  const bool was = this->Impl->cursor->GetVisibility() != 0;
  if (this->PlaceCursor(x, y) || was)
    this->Render();
}

bool vtkPaintView::PlaceCursor(int x, int y)
{
  Internals& in = *this->Impl;
  double p[3], n[3];
  const bool on = this->PickFacing(x, y, p, n);
  if (on) {
    const double lift = 0.02 * in.brush->radius(); // above the surface, so it is not hidden in it
    in.cursor_shape->SetCenter(p[0] + lift * n[0], p[1] + lift * n[1], p[2] + lift * n[2]);
    in.cursor_shape->SetNormal(n);
    in.cursor_shape->SetRadius(in.brush->radius());
  }
  in.cursor->SetVisibility(on);
  return on;
}

vtkIdType vtkPaintView::GetFaceCount()
{
  vtkIdType faces = 0;
  for (std::size_t o = 0; o < this->Impl->drawings.size(); ++o) {
    const Drawing& d = *this->Impl->drawings[o];
    faces += d.full ? d.full->GetNumberOfCells() : this->Surface(o, this->Level)->GetNumberOfCells();
  }
  return faces;
}

int vtkPaintView::PickObject(int x, int y)
{
  double p[3], n[3];
  return this->PickFacing(x, y, p, n) ? this->Impl->picker->GetActorIndex() : -1;
}

bool vtkPaintView::IsSharingArrays(int object)
{
  const auto& drawings = this->Impl->drawings;
  return object >= 0 && std::size_t(object) < drawings.size() && drawings[std::size_t(object)]->shared;
}

int vtkPaintView::GetShownLevel() { return this->Impl->shown_level; }

int vtkPaintView::CoarseLevel()
{
  if (this->LodLevel == 0)
    return this->Level;
  if (this->LodLevel > 0)
    return std::min(this->LodLevel, this->Level);
  // Automatic: the finest level below the painting level whose drawing, at
  // the rate timed at rest, takes at most half a frame at LodFrameRate (the
  // other half is left to the brush step and the display update).
  const double budget_ms = 500.0 / this->LodFrameRate;
  int level = std::max(1, this->Level - 1);
  double faces = double(this->GetFaceCount()) / 4.0;
  for (; level > 1 && faces * this->Impl->ms_per_face > budget_ms; --level)
    faces /= 4.0;
  return level;
}

void vtkPaintView::SetAntiAliasing(bool on)
{
  if (this->AntiAliasing == on)
    return;
  this->AntiAliasing = on;
  this->Impl->renderer->SetUseFXAA(on && !this->Impl->moving);
  this->Modified();
}

int vtkPaintView::GetLodLevelInUse() { return this->CoarseLevel(); }

vtkPolyData* vtkPaintView::Surface(std::size_t object, int level)
{
  Internals& in = *this->Impl;
  Drawing& d = *in.drawings[object];
  meshpaint::PaintSurface& surface = in.scene.surface(object);
  if (!d.full) {
    d.full_count = surface.change_count();
    d.full = meshpaint::to_polydata(surface.painted_surface());
    d.coarse = nullptr;
    // Where the device's memory is the host's, the arrays drawn are the
    // engine's own: a kernel writes the patches that change, in place.
    const auto shared = this->ShareArrays ? surface.display_arrays() : nullptr;
    if (shared) {
      meshpaint::share_arrays(d.full, shared);
      d.seen.clear();
      for (std::size_t k = 0; k < shared->arrays().size(); ++k)
        d.seen.push_back(shared->version(k));
    }
    d.shared = shared != nullptr;
  } else if (d.full_stale) {
    // Same topology: only the vertices of the patches that changed are
    // written (on the device into the shared arrays, else read back into
    // VTK's), and only the arrays that changed are marked (and uploaded).
    const meshpaint::PatchChanges changes = surface.changes_since(d.full_count);
    d.full_count = surface.change_count();
    const auto shared = d.shared ? surface.display_arrays() : nullptr; // brought up to date
    if (shared) {
      if (meshpaint::refresh_shared_arrays(d.full, shared, d.seen))
        d.coarse = nullptr; // it shares the arrays that moved
    } else if (changes.all) {
      meshpaint::update_polydata(d.full, surface.painted_surface());
    } else {
      meshpaint::update_polydata(d.full, surface.painted_vertices(changes.patches));
    }
  }
  d.full_stale = false;
  if (level == this->Level)
    return d.full;
  // A coarser tessellation of the same painted surface, sharing its points
  // and arrays; the atlas is not touched (a reduction there would start
  // multiresolution edits afresh).
  if (!d.coarse || d.coarse_level != level) {
    const int n = 1 << (this->Level - 1), stride = 1 << (this->Level - level);
    d.coarse = meshpaint::coarser_quads(d.full, n, stride);
    d.coarse_level = level;
  }
  return d.coarse;
}

void vtkPaintView::Show()
{
  Internals& in = *this->Impl;
  const int level = in.moving ? this->CoarseLevel() : this->Level;
  const bool lit = this->SubsurfacePasses > 0 && level == this->Level && in.initialized;
  for (std::size_t o = 0; o < in.drawings.size(); ++o) {
    Drawing& d = *in.drawings[o];
    vtkPolyData* poly = nullptr;
    if (!meshpaint::guarded(this->LastError, [&] { poly = this->Surface(o, level); }))
      return;
    if (lit) { // at rest only: the light follows the camera
      meshpaint::guarded(this->LastError, [&] {
        vtkCamera* camera = in.renderer->GetActiveCamera();
        double eye[3], focus[3];
        camera->GetPosition(eye);
        camera->GetFocalPoint(focus);
        const std::vector<float> light = in.scene.surface(o).scattered_light(
          {float(eye[0] - focus[0]), float(eye[1] - focus[1]), float(eye[2] - focus[2])}, this->SubsurfacePasses);
        auto array = vtkSmartPointer<vtkFloatArray>::New();
        array->SetName("scattered_light");
        array->SetNumberOfValues(vtkIdType(light.size()));
        std::copy(light.begin(), light.end(), array->GetPointer(0));
        poly->GetPointData()->AddArray(array);
      });
      meshpaint::show_scattered_light(d.actor, poly);
    } else if (in.lit && in.initialized) {
      poly->GetPointData()->RemoveArray("scattered_light");
      meshpaint::show_materials(d.actor, poly);
    } else if (poly != d.shown.GetPointer() && in.initialized) {
      d.actor->GetMapper()->SetInputDataObject(poly);
    }
    d.shown = poly;
  }
  in.renderer->SetUseFXAA(this->AntiAliasing && !in.moving);
  in.lit = lit;
  in.shown_level = level;
}

void vtkPaintView::Refresh(bool geometry)
{
  Internals& in = *this->Impl;
  if (in.scene.empty())
    return;
  for (const auto& d : in.drawings)
    d->full_stale = true;
  // Within a stroke the buffers stay: the picker keeps the surface they saw.
  if (geometry && !in.painting)
    in.picker->Release();
  this->Show();
  this->UpdateText();
  this->Render();
}

void vtkPaintView::SetMoving(bool moving)
{
  Internals& in = *this->Impl;
  if (in.painting || in.scene.empty())
    return;
  in.moving = moving;
  this->Show();
  if (!in.moving)
    this->Render(); // the full level, now that the view rests
}

void vtkPaintView::OnCameraInteraction(vtkObject*, unsigned long event, void*)
{
  this->SetMoving(event == vtkCommand::StartInteractionEvent);
}

int vtkPaintView::HandleKey(const char* keysym, bool control, bool shift)
{
  Internals& in = *this->Impl;
  if (!keysym || !in.brush)
    return 0;
  const std::string key = keysym;
  if (control) {
    if (key == "z" || key == "Z")
      this->Undo();
    else if (key == "y" || key == "Y")
      this->Redo();
    else if (key == "s" || key == "S")
      this->Save();
    else if (key == "e" || key == "E")
      this->Export();
    else
      return 0;
  } else if (key == "h" || key == "F1" || key == "question") {
    this->SetHelpVisible(!this->GetHelpVisible());
  } else if (key == "b") {
    this->SubsurfacePasses = this->SubsurfacePasses > 0 ? 0 : 60;
    this->Message = this->SubsurfacePasses > 0 ? "subsurface light on" : "subsurface light off";
    this->Show();
  } else if (key == "r") {
    meshpaint::set_camera(in.renderer, meshpaint::CameraView());
  } else if (key == "q" || key == "Escape") {
    if (in.initialized)
      in.interactor->TerminateApp();
    return 1;
  } else if (!in.brush->handle_key(key, shift)) {
    return 0;
  }
  this->UpdateText();
  this->Render();
  return 1;
}

int vtkPaintView::Step(bool back)
{
  Internals& in = *this->Impl;
  bool done = false;
  const int ok = !in.scene.empty() && meshpaint::guarded(this->LastError, [&] {
    done = back ? in.scene.undo() : in.scene.redo();
  });
  this->Message = !ok ? this->LastError : done ? (back ? "undone" : "redone") : (back ? "nothing to undo" : "nothing to redo");
  this->Refresh(true);
  return ok && done;
}

int vtkPaintView::Undo() { return this->Step(true); }

int vtkPaintView::Redo() { return this->Step(false); }

const char* vtkPaintView::GetRecording()
{
  Internals& in = *this->Impl;
  meshpaint::StrokeScript script;
  script.level = this->Level;
  script.strokes = in.scene.history();
  in.recording = meshpaint::stroke_script_json(script);
  return in.recording.c_str();
}

namespace {

//! Creates `dir` (and its parents) unless it exists.
void make_directory(const std::string& dir)
{
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec)
    throw meshpaint::IOError("cannot create '" + dir + "': " + ec.message());
}

} // namespace

int vtkPaintView::Save()
{
  Internals& in = *this->Impl;
  const std::string dir = this->SaveDirectory;
  // One recording for the scene; each object's surface in its own folder.
  const int ok = !in.scene.empty() && meshpaint::guarded(this->LastError, [&] {
    make_directory(dir);
    const std::string recording = this->GetRecording();
    meshpaint::write_atomically(dir + "/strokes.json", [&](const std::string& tmp) {
      std::ofstream out(tmp, std::ios::binary);
      out << recording;
      if (!out.flush())
        throw meshpaint::IOError("cannot write '" + dir + "/strokes.json'");
    });
    for (std::size_t o = 0; o < in.scene.size(); ++o) {
      const std::string folder = in.scene.folder(dir, o);
      make_directory(folder);
      meshpaint::write_vtp(this->Surface(o, this->Level), folder + "/surface.vtp");
    }
    if (in.project) {
      meshpaint::Project p = *in.project;
      p.history = meshpaint::continued_history(in.project->history, in.scene.history(), this->Level);
      meshpaint::capture_surface(in.scene.surface(0), p);
      meshpaint::save_project(p, in.scene.folder(dir, 0) + "/surface.meshpaint");
    }
  });
  const std::string surfaces =
    in.scene.size() == 1 ? "surface.vtp" : std::to_string(in.scene.size()) + " objects' surface.vtp";
  this->Message = ok ? "saved " + dir + "/strokes.json, " + surfaces + (in.project ? " and surface.meshpaint" : "")
                     : this->LastError;
  this->UpdateText();
  this->Render();
  return ok;
}

int vtkPaintView::Export()
{
  Internals& in = *this->Impl;
  const std::string dir = this->SaveDirectory;
  const int ok = !in.scene.empty() && meshpaint::guarded(this->LastError, [&] {
    for (std::size_t o = 0; o < in.scene.size(); ++o) {
      const std::string folder = in.scene.folder(dir, o);
      make_directory(folder);
      meshpaint::ExportModel model;
      meshpaint::TextureMaps maps;
      meshpaint::build_export(in.scene.surface(o), std::max(1, this->Level - 2), model, maps);
      meshpaint::write_texture_maps(maps, folder);
      meshpaint::write_obj_model(model, maps, folder);
    }
  });
  this->Message = ok ? "exported " + in.scene.folder(dir, 0) + "/model.obj" +
                         (in.scene.size() > 1 ? " and the other objects'" : "")
                     : this->LastError;
  this->UpdateText();
  this->Render();
  return ok;
}

void vtkPaintView::SetHelpVisible(bool visible)
{
  this->Impl->help->SetVisibility(visible);
  this->Render();
}

bool vtkPaintView::GetHelpVisible() { return this->Impl->help->GetVisibility() != 0; }

void vtkPaintView::UpdateText()
{
  Internals& in = *this->Impl;
  if (!in.initialized || !in.brush)
    return;
  const int* size = in.window->GetSize();
  in.help->SetPosition(10, size[1] - 10);
  std::string text = in.brush->describe() + "\nlevel " + std::to_string(this->Level) + " (level of detail " +
                     std::to_string(this->CoarseLevel()) + ")   strokes " +
                     std::to_string(in.scene.history().size()) + "   h: help";
  if (!this->Message.empty())
    text += "   | " + this->Message;
  in.status->SetInput(text.c_str());
}
