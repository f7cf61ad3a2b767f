#include "vtkPaintView.h"
#include "vtkPaintViewInternals.h"

#include "CallGuard.h"        // for meshpaint::guarded
#include "ChannelDisplay.h"   // for meshpaint::show_channel, parse_shown_channel
#include "PaintingExport.h"   // for meshpaint::default_model_level
#include "SceneFiles.h"       // for meshpaint::save_session, export_scene
#include "SurfaceRendering.h" // for meshpaint::show_materials, show_scattered_light, add_scattered_light, set_camera
#include "WindowKeys.h"       // for meshpaint::window_key, window_help

#include "core/errors.h"             // for meshpaint::InputError
#include "project/labels.h"          // for meshpaint::LabelClass, parse_labels, labels_json
#include "project/project_surface.h" // for meshpaint::save_painted_project

#include <vtkCamera.h>        // for vtkCamera
#include <vtkCommand.h>       // for vtkCommand::UpdateDataEvent
#include <vtkMapper.h>        // for vtkMapper
#include <vtkObjectFactory.h> // for vtkStandardNewMacro
#include <vtkPointData.h>     // for vtkPointData
#include <vtkPolyData.h>      // for vtkPolyData

#include <algorithm> // for std::min, std::max, std::remove_if, std::sort, std::find
#include <chrono>    // for std::chrono::steady_clock

vtkStandardNewMacro(vtkPaintView);

vtkPaintView::vtkPaintView() : Impl(new Internals(this)) {}

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

int vtkPaintView::Initialize()
{
  Internals& in = *this->Impl;
  if (in.scene.empty()) {
    this->LastError = "no surface to paint: load a mesh first";
    return 0;
  }
  if (in.initialized)
    return 1;
  in.cursor.picker()->RemoveAllActors();
  for (std::size_t o = 0; o < in.drawings.size(); ++o)
    this->ShowObject(o);
  in.renderer->SetBackground(0.12, 0.12, 0.14);
  in.cursor.add_to(in.renderer);
  in.text.add_to(in.renderer, meshpaint::window_help());
  in.legend.add_to(in.renderer);

  in.window->AddRenderer(in.renderer);
  if (!in.hosted)
    in.window->SetSize(this->Size);
  // Multisampling triples the cost of a frame on a software rasterizer;
  // FXAA smooths the edges of frames at rest instead (see Show()).
  in.window->SetMultiSamples(0);
  in.renderer->SetUseFXAA(this->AntiAliasing);
  if (!in.hosted) {
    in.window->SetOffScreenRendering(this->OffScreen ? 1 : 0);
    in.window->SetWindowName("meshpaint");
    in.interactor->SetRenderWindow(in.window);
  }
  in.style->SetControls(&in.controls);
  in.interactor->SetInteractorStyle(in.style);
  in.cursor.picker()->SetRenderer(in.renderer);
  in.cursor.picker()->SetPatchResolution(1 << (this->Level - 1)); // captures happen at rest: the full level
  meshpaint::set_camera(in.renderer, meshpaint::CameraView());
  if (!in.hosted)
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
  const std::chrono::duration<double, std::milli> took = std::chrono::steady_clock::now() - start;
  const int* size = in.window->GetSize();
  in.timing.add_frame(took.count(), size[0], size[1], double(this->GetFaceCount()));
}

void vtkPaintView::SetRenderWindow(vtkRenderWindow* window)
{
  Internals& in = *this->Impl;
  if (!window || in.initialized)
    return;
  in.window = window;
  if (window->GetInteractor())
    in.interactor = window->GetInteractor();
  else
    in.interactor->SetRenderWindow(window);
  in.hosted = true;
}

double vtkPaintView::GetLastStepTime() { return this->Impl->step_ms; }

vtkRenderWindow* vtkPaintView::GetRenderWindow() { return this->Impl->window; }
vtkRenderer* vtkPaintView::GetRenderer() { return this->Impl->renderer; }
vtkRenderWindowInteractor* vtkPaintView::GetInteractor() { return this->Impl->interactor; }
vtkSurfacePicker* vtkPaintView::GetPicker() { return this->Impl->cursor.picker(); }

bool vtkPaintView::PickFacing(int x, int y, double point[3], double normal[3])
{
  Internals& in = *this->Impl;
  return in.initialized &&
         in.cursor.pick_facing(in.renderer, in.window, x, y, this->SilhouetteCosine, point, normal);
}

void vtkPaintView::MoveCursor(int x, int y)
{
  const bool was = this->Impl->cursor.visible();
  if (this->PlaceCursor(x, y) || was)
    this->Render();
}

bool vtkPaintView::PlaceCursor(int x, int y)
{
  Internals& in = *this->Impl;
  double p[3], n[3];
  const bool on = this->PickFacing(x, y, p, n);
  in.cursor.place(on, p, n, on ? in.brush->radius() : 0.0);
  return on;
}

int vtkPaintView::PickObject(int x, int y)
{
  double p[3], n[3];
  return this->PickFacing(x, y, p, n) ? this->Impl->cursor.picker()->GetActorIndex() : -1;
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
  return this->Impl->timing.automatic_level(this->Level, this->LodFrameRate, double(this->GetFaceCount()));
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
  return meshpaint::drawn_surface(*in.drawings[object], in.scene.surface(object), level, this->Level,
                                  this->ShareArrays);
}

void vtkPaintView::Show()
{
  Internals& in = *this->Impl;
  // Drawing is not a call of its own: its failures go to the status line,
  // and a success leaves the reason the call before it failed in LastError.
  std::string error;
  const auto attempt = [&](auto&& f) {
    const int ok = meshpaint::guarded(error, f);
    if (!ok)
      this->LastError = this->Message = error;
    return ok;
  };
  const int level = in.moving ? this->CoarseLevel() : this->Level;
  const bool lit = this->SubsurfacePasses > 0 && level == this->Level && in.initialized &&
                   in.shown == meshpaint::ShownChannel::diffuse;
  for (std::size_t o = 0; o < in.drawings.size(); ++o) {
    meshpaint::ObjectDrawing& d = *in.drawings[o];
    vtkPolyData* poly = nullptr;
    if (!attempt([&] { poly = this->Surface(o, level); }))
      return;
    if (lit) { // at rest only: the light follows the camera
      attempt([&] {
        vtkCamera* camera = in.renderer->GetActiveCamera();
        double eye[3], focus[3];
        camera->GetPosition(eye);
        camera->GetFocalPoint(focus);
        meshpaint::add_scattered_light(poly, in.scene.surface(o),
                                       {eye[0] - focus[0], eye[1] - focus[1], eye[2] - focus[2]},
                                       this->SubsurfacePasses);
      });
      meshpaint::show_scattered_light(d.actor, poly);
    } else if (in.shown != meshpaint::ShownChannel::diffuse && in.initialized) {
      // Colours made from the channel: again after every change.
      attempt([&] { meshpaint::show_channel(d.actor, poly, in.shown, in.labels, in.hidden_labels); });
    } else if ((in.lit || in.channel_drawn) && in.initialized) {
      poly->GetPointData()->RemoveArray("scattered_light");
      meshpaint::show_materials(d.actor, poly);
    } else if (poly != d.shown.GetPointer() && in.initialized) {
      d.actor->GetMapper()->SetInputDataObject(poly);
    }
    d.shown = poly;
  }
  in.renderer->SetUseFXAA(this->AntiAliasing && !in.moving);
  if (in.initialized && !in.drawings.empty())
    attempt([&] {
      // Hidden classes are not in the legend; ids painted without a class are, by their number.
      const std::vector<meshpaint::LabelClass> shown_classes =
        in.shown == meshpaint::ShownChannel::label && !lit
          ? meshpaint::shown_label_classes(in.drawings.front()->shown, in.labels, in.hidden_labels)
          : std::vector<meshpaint::LabelClass>();
      in.legend.update(lit ? meshpaint::ShownChannel::diffuse : in.shown, in.drawings.front()->shown, shown_classes);
    });
  in.channel_drawn = in.shown != meshpaint::ShownChannel::diffuse && !lit && in.initialized;
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
    in.cursor.picker()->Release();
  this->Show();
  this->UpdateText();
  this->Render();
}

vtkPolyData* vtkPaintView::GetPaintedPolyData(int object)
{
  Internals& in = *this->Impl;
  if (object < 0 || std::size_t(object) >= in.drawings.size())
    return nullptr;
  vtkPolyData* poly = nullptr;
  meshpaint::guarded(this->LastError, [&] { poly = this->Surface(std::size_t(object), this->Level); });
  return poly;
}

void vtkPaintView::SetLocked(bool locked)
{
  if (this->Locked == locked)
    return;
  this->Locked = locked;
  this->Modified();
}

bool vtkPaintView::RefusedWhileLocked()
{
  if (!this->Locked)
    return false;
  this->LastError = "busy: the surface is being exported or rebuilt, wait for it to finish";
  this->Message = this->LastError;
  this->UpdateText();
  return true;
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

int vtkPaintView::HandleKey(const char* keysym, bool control, bool shift)
{
  Internals& in = *this->Impl;
  if (!keysym || !in.brush)
    return 0;
  const std::string key = keysym;
  switch (meshpaint::window_key(key, control)) {
    case meshpaint::WindowKey::none:
      return 0;
    case meshpaint::WindowKey::brush:
      if (!in.brush->handle_key(key, shift))
        return 0;
      break;
    case meshpaint::WindowKey::undo:
      this->Undo();
      break;
    case meshpaint::WindowKey::redo:
      this->Redo();
      break;
    case meshpaint::WindowKey::save:
      this->Save();
      break;
    case meshpaint::WindowKey::export_model:
      this->Export();
      break;
    case meshpaint::WindowKey::help:
      this->SetHelpVisible(!this->GetHelpVisible());
      break;
    case meshpaint::WindowKey::subsurface:
      if (this->RefusedWhileLocked())
        return 1;
      this->SubsurfacePasses = this->SubsurfacePasses > 0 ? 0 : 60;
      this->Message = this->SubsurfacePasses > 0 ? "subsurface light on" : "subsurface light off";
      this->Show();
      break;
    case meshpaint::WindowKey::shown_next:
    case meshpaint::WindowKey::shown_back: {
      const int n = int(meshpaint::shown_channel_names().size());
      const bool back = shift || meshpaint::window_key(key, control) == meshpaint::WindowKey::shown_back;
      in.shown = meshpaint::ShownChannel((int(in.shown) + (back ? n - 1 : 1)) % n);
      this->Message = "showing " + meshpaint::shown_channel_name(in.shown);
      this->Show();
      break;
    }
    case meshpaint::WindowKey::reset_camera:
      meshpaint::set_camera(in.renderer, meshpaint::CameraView());
      break;
    case meshpaint::WindowKey::eyedropper: {
      const int* at = in.interactor->GetEventPosition();
      if (!this->PickAt(at[0], at[1]))
        this->Message = "nothing to pick: no surface under the mouse";
      break;
    }
    case meshpaint::WindowKey::fill:
    case meshpaint::WindowKey::fill_connect: {
      if (shift || meshpaint::window_key(key, control) == meshpaint::WindowKey::fill_connect) { // G: g with Shift
        in.brush->set_fill_diagonals(!in.brush->fill_diagonals());
        this->Message = in.brush->fill_diagonals() ? "fills connect across corners too (diagonals)"
                                                   : "fills connect along sides only";
        break;
      }
      const int* at = in.interactor->GetEventPosition();
      if (this->RefusedWhileLocked())
        return 1;
      if (!this->FillAt(at[0], at[1]) && this->Message != this->LastError)
        this->Message = "nothing to fill: no surface under the mouse";
      break;
    }
    case meshpaint::WindowKey::quit:
      this->InvokeEvent(vtkCommand::ExitEvent); // a host window (the studio) closes itself on it
      if (in.initialized)
        in.interactor->TerminateApp();
      return 1;
  }
  this->UpdateText();
  this->Render();
  return 1;
}

int vtkPaintView::Save()
{
  Internals& in = *this->Impl;
  if (this->RefusedWhileLocked())
    return 0;
  std::string message;
  const int ok = !in.scene.empty() && meshpaint::guarded(this->LastError, [&] {
    message = meshpaint::save_session(
      in.scene, this->GetRecording(), [&](std::size_t o) { return this->Surface(o, this->Level); }, in.labels,
      in.project.get(), in.origin, this->SaveDirectory);
  });
  this->Message = ok ? message : this->LastError;
  this->UpdateText();
  this->Render();
  return ok;
}

int vtkPaintView::SaveProject(const char* path)
{
  Internals& in = *this->Impl;
  if (this->RefusedWhileLocked())
    return 0;
  const int ok = meshpaint::guarded(this->LastError, [&] {
    if (in.scene.size() != 1)
      throw meshpaint::InputError("a project keeps one surface: this scene has " + std::to_string(in.scene.size()));
    meshpaint::Project base = in.project ? *in.project : meshpaint::Project();
    base.labels = in.labels;
    base.origin = in.origin;
    in.origin = meshpaint::save_painted_project(in.scene.surface(0), std::move(base), path ? path : "");
  });
  this->Message = ok ? std::string("saved ") + path : this->LastError;
  this->UpdateText();
  this->Render();
  return ok;
}

int vtkPaintView::Export()
{
  Internals& in = *this->Impl;
  if (this->RefusedWhileLocked())
    return 0;
  std::string message;
  const int ok = !in.scene.empty() && meshpaint::guarded(this->LastError, [&] {
    message = meshpaint::export_scene(in.scene, meshpaint::default_model_level(this->Level), this->SaveDirectory);
  });
  this->Message = ok ? message : this->LastError;
  this->UpdateText();
  this->Render();
  return ok;
}

void vtkPaintView::SetHelpVisible(bool visible)
{
  this->Impl->text.set_help_visible(visible);
  this->Render();
}

bool vtkPaintView::GetHelpVisible() { return this->Impl->text.help_visible(); }

void vtkPaintView::UpdateText()
{
  Internals& in = *this->Impl;
  if (in.initialized && in.brush)
    in.text.update(meshpaint::status_line(in.brush->describe(), this->Level, this->CoarseLevel(),
                                          in.scene.history().size(), this->Message),
                   in.window->GetSize()[1]);
  this->InvokeEvent(vtkCommand::UpdateDataEvent);
}

int vtkPaintView::SetShownChannel(const char* name)
{
  Internals& in = *this->Impl;
  if (!meshpaint::guarded(this->LastError, [&] { in.shown = meshpaint::parse_shown_channel(name ? name : ""); }))
    return 0;
  if (!in.scene.empty())
    this->Show();
  this->UpdateText();
  this->Render();
  return 1;
}

const char* vtkPaintView::GetShownChannel() { return meshpaint::shown_channel_name(this->Impl->shown).c_str(); }

int vtkPaintView::AddLabelClass(int id, const char* name, double r, double g, double b)
{
  std::vector<meshpaint::LabelClass> labels = this->Impl->labels;
  labels.erase(std::remove_if(labels.begin(), labels.end(), [&](const meshpaint::LabelClass& c) { return c.id == id; }),
               labels.end());
  meshpaint::LabelClass c;
  c.id = id;
  c.name = name ? name : "";
  c.colour = {float(r), float(g), float(b)};
  labels.push_back(c);
  std::sort(labels.begin(), labels.end(),
            [](const meshpaint::LabelClass& a, const meshpaint::LabelClass& b) { return a.id < b.id; });
  // The checks of a labels file: ids, names and colours.
  if (!meshpaint::guarded(this->LastError, [&] { meshpaint::parse_labels(meshpaint::labels_json(labels)); }))
    return 0;
  this->SetLabelClasses(labels);
  return 1;
}

void vtkPaintView::RemoveLabelClass(int id)
{
  std::vector<meshpaint::LabelClass> labels = this->Impl->labels;
  labels.erase(std::remove_if(labels.begin(), labels.end(), [&](const meshpaint::LabelClass& c) { return c.id == id; }),
               labels.end());
  this->SetLabelClasses(labels);
}

void vtkPaintView::SetLabelClassVisible(int id, bool visible)
{
  Internals& in = *this->Impl;
  in.hidden_labels.erase(std::remove(in.hidden_labels.begin(), in.hidden_labels.end(), id), in.hidden_labels.end());
  if (!visible)
    in.hidden_labels.push_back(id);
  if (in.shown == meshpaint::ShownChannel::label && !in.scene.empty())
    this->Show();
  this->Render();
}

bool vtkPaintView::GetLabelClassVisible(int id)
{
  const std::vector<int>& h = this->Impl->hidden_labels;
  return std::find(h.begin(), h.end(), id) == h.end();
}

void vtkPaintView::RemoveAllLabelClasses() { this->SetLabelClasses({}); }

int vtkPaintView::GetNumberOfLabelClasses() { return int(this->Impl->labels.size()); }

const std::vector<meshpaint::LabelClass>& vtkPaintView::GetLabelClasses() const { return this->Impl->labels; }

void vtkPaintView::SetLabelClasses(const std::vector<meshpaint::LabelClass>& labels)
{
  Internals& in = *this->Impl;
  in.labels = labels;
  if (in.project)
    in.project->labels = labels; // what a save keeps
  if (in.shown == meshpaint::ShownChannel::label && !in.scene.empty())
    this->Show();
  this->UpdateText();
  this->Render();
}

meshpaint::BrushSettings* vtkPaintView::GetBrush() { return this->Impl->brush.get(); }

meshpaint::PaintScene& vtkPaintView::GetScene() { return this->Impl->scene; }

const meshpaint::Project* vtkPaintView::GetProject() const { return this->Impl->project.get(); }

const meshpaint::ProjectOrigin& vtkPaintView::GetProjectOrigin() const { return this->Impl->origin; }
