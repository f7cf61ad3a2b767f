// vtkPaintView's scene: the objects painted, from mesh files, polygons,
// engine meshes, engine surfaces others hold too, or a vtkPaintSurface.
#include "vtkPaintView.h"
#include "vtkPaintViewInternals.h"

#include "CallGuard.h"         // for meshpaint::guarded
#include "PolyDataFiles.h"     // for meshpaint::import_polydata
#include "SurfaceRendering.h"  // for meshpaint::show_materials
#include "vtkPaintSurface.h"   // for vtkPaintSurface

#include "core/errors.h"         // for meshpaint::InputError
#include "mesh/base_mesh.h"      // for meshpaint::BaseMesh, load_mesh
#include "paint/paint_surface.h" // for meshpaint::PaintSurface
#include "project/imported_channels.h" // for meshpaint::apply_imported_channels
#include "project/imported_labels.h" // for meshpaint::apply_imported_labels, imported_label_classes

#include <vtkBoundingBox.h> // for vtkBoundingBox
#include <vtkPolyData.h>    // for vtkPolyData

#include <algorithm> // for std::none_of, std::stable_sort

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
        mesh = meshpaint::import_polydata(polygons, "input", "input polygons: ");
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
    meshpaint::apply_imported_channels(*surface);
    meshpaint::apply_imported_labels(*surface);
    if (!add)
      this->RemoveObjects();
    this->AddObject(std::move(surface), mesh.name);
    // The file's classes (or one per label id), shown in their colours, kept
    // by a save; an object added keeps the classes there and brings its own ids.
    std::vector<meshpaint::LabelClass> labels = add ? in.labels : std::vector<meshpaint::LabelClass>();
    for (const meshpaint::LabelClass& c : meshpaint::imported_label_classes(mesh))
      if (std::none_of(labels.begin(), labels.end(), [&](const meshpaint::LabelClass& k) { return k.id == c.id; }))
        labels.push_back(c);
    std::stable_sort(labels.begin(), labels.end(),
                     [](const meshpaint::LabelClass& a, const meshpaint::LabelClass& b) { return a.id < b.id; });
    in.labels = labels;
  });
}

void vtkPaintView::SetProject(const meshpaint::Project& project)
{
  this->Impl->project = std::make_unique<meshpaint::Project>(project);
  this->Impl->origin = project.origin;
  this->Impl->labels = project.labels; // shown in their colours, kept by a save
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

int vtkPaintView::SetPaintSurface(vtkPaintSurface* filter)
{
  if (!filter) {
    this->LastError = "no vtkPaintSurface to paint on";
    return 0;
  }
  filter->Update();
  std::shared_ptr<meshpaint::PaintSurface> surface = filter->GetPaintSurface();
  if (!surface) {
    this->LastError = *filter->GetLastError() ? filter->GetLastError() : "the vtkPaintSurface has no surface";
    return 0;
  }
  return meshpaint::guarded(this->LastError, [&] {
    this->SetDevice(filter->GetDevice());
    this->SetSurface(std::move(surface));
    if (const meshpaint::Project* project = filter->GetProject()) // saves here continue the loaded project
      this->SetProject(*project);
  });
}

void vtkPaintView::RemoveObjects()
{
  Internals& in = *this->Impl;
  if (in.initialized) {
    for (const auto& d : in.drawings)
      in.renderer->RemoveActor(d->actor);
    in.cursor.picker()->RemoveAllActors();
  }
  in.drawings.clear();
  in.scene.clear();
  in.project.reset();
  in.origin = {};
}

void vtkPaintView::AddObject(std::shared_ptr<meshpaint::PaintSurface> surface, const std::string& name)
{
  Internals& in = *this->Impl;
  in.scene.add(std::move(surface), name); // checks the level
  this->Level = in.scene.surface(0).level();
  in.drawings.push_back(std::make_unique<meshpaint::ObjectDrawing>());
  in.timing.reset(); // other objects draw at another rate
  in.moving = false;
  in.shown_level = this->Level;
  meshpaint::ObjectDrawing& d = *in.drawings.back();
  d.shown = this->Surface(in.drawings.size() - 1, this->Level);
  // The brush is sized to the whole scene.
  vtkBoundingBox box;
  for (const auto& other : in.drawings)
    box.AddBounds(other->full->GetBounds());
  in.brush = std::make_unique<meshpaint::BrushSettings>(box.GetDiagonalLength(), this->Level);
  if (in.initialized) {
    this->ShowObject(in.drawings.size() - 1);
    in.cursor.picker()->SetPatchResolution(1 << (this->Level - 1));
  }
  this->Modified();
}

void vtkPaintView::ShowObject(std::size_t object)
{
  Internals& in = *this->Impl;
  meshpaint::ObjectDrawing& d = *in.drawings[object];
  meshpaint::show_materials(d.actor, d.shown);
  in.renderer->AddActor(d.actor);
  in.cursor.picker()->AddActor(d.actor);
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

vtkIdType vtkPaintView::GetFaceCount()
{
  vtkIdType faces = 0;
  for (std::size_t o = 0; o < this->Impl->drawings.size(); ++o) {
    const meshpaint::ObjectDrawing& d = *this->Impl->drawings[o];
    faces += d.full ? d.full->GetNumberOfCells() : this->Surface(o, this->Level)->GetNumberOfCells();
  }
  return faces;
}
