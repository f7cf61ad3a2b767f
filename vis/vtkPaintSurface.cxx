#include "vtkPaintSurface.h"

#include "PaintingExport.h"    // for meshpaint::export_painting, default_model_level
#include "CallGuard.h"         // for meshpaint::guarded
#include "PolyDataFiles.h"     // for meshpaint::import_polydata
#include "RasterIO.h"          // for meshpaint::load_stroke_rasters
#include "SharedArrays.h"      // for meshpaint::share_arrays, refresh_shared_arrays
#include "SurfaceConversion.h" // for meshpaint::to_polydata

#include "atlas/patch_layout.h"        // for meshpaint::kMaxLevel
#include "core/errors.h"               // for meshpaint::InputError
#include "paint/paint_surface.h"       // for meshpaint::PaintSurface
#include "paint/stroke_session.h"      // for meshpaint::StrokeSession
#include "project/imported_channels.h"  // for meshpaint::apply_imported_channels
#include "project/imported_labels.h"  // for meshpaint::apply_imported_labels, imported_label_classes
#include "project/project_surface.h"   // for meshpaint::open_project_surface, save_painted_project
#include "project/vertex_channels.h"   // for meshpaint::vertex_channel, set_vertex_channel

#include <nlohmann/json.hpp> // for nlohmann::json

#include <optional> // for std::optional

#include <vtkAlgorithm.h>         // for vtkAlgorithm::INPUT_IS_OPTIONAL
#include <vtkDataArray.h>         // for vtkDataArray
#include <vtkFloatArray.h>        // for vtkFloatArray
#include <vtkInformation.h>       // for vtkInformation
#include <vtkIntArray.h>          // for vtkIntArray
#include <vtkInformationVector.h> // for vtkInformationVector
#include <vtkObjectFactory.h>     // for vtkStandardNewMacro
#include <vtkPoints.h>            // for vtkPoints
#include <vtkPolyData.h>          // for vtkPolyData
#include <vtkSmartPointer.h>      // for vtkSmartPointer

#include <algorithm> // for std::min
#include <map>       // for std::map
#include <vector>    // for std::vector

vtkStandardNewMacro(vtkPaintSurface);

struct vtkPaintSurface::Internals
{
  nlohmann::json brush = {{"tool", "paint"}}; // the setters' stroke, without points
  std::string brush_text;
  std::shared_ptr<meshpaint::PaintSurface> surface; // shared with painting windows shown on it
  // The strokes go through a session, as the window's and the command line's do.
  meshpaint::PaintScene scene;
  meshpaint::StrokeSession session{scene};
  void set_surface(std::shared_ptr<meshpaint::PaintSurface> s)
  {
    surface = std::move(s);
    scene.clear();
    scene.add(surface, "input");
  }
  vtkMTimeType built_from = 0; // input's modification time the surface was built from
  int built_level = 0;
  bool built_welded = true;
  std::vector<meshpaint::ArrayImport> imports; // AddImportArray()
  bool imports_changed = false;                // since the surface was built
  std::vector<meshpaint::Stroke> queued;
  //! The loaded project, without its layers: history, labels, scan and
  //! reference to carry into the next save.
  std::optional<meshpaint::Project> project;
  //! The label classes: the loaded project's, or those of the input's file
  //! data and label ids (imported_label_classes()).
  std::vector<meshpaint::LabelClass> labels;
  //! The file this surface was last loaded from or saved to, as it was then.
  meshpaint::ProjectOrigin origin;
  std::map<std::string, vtkSmartPointer<vtkDataArray>> channels; // arrays handed out by GetChannel
  std::string history_text;                                      // what GetHistoryJSON() returned
  // ShareArrays: the output's arrays over the surface's display arrays, the
  // surface they belong to, and the arrays' versions they were marked for.
  vtkSmartPointer<vtkPolyData> shared;
  std::weak_ptr<meshpaint::PaintSurface> shared_from;
  std::vector<std::uint64_t> shared_seen;
};

vtkPaintSurface::vtkPaintSurface() : Impl(new Internals) {}
vtkPaintSurface::~vtkPaintSurface() = default;

void vtkPaintSurface::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Level: " << this->Level << "\n";
  os << indent << "Device: " << (this->Device.empty() ? "(default)" : this->Device) << "\n";
  os << indent << "StrokeCount: " << this->StrokeCount << "\n";
}

// Each setter writes its stroke-script key; checking happens once, in
// ApplyStroke(), by the same parser that reads scripts.
void vtkPaintSurface::SetTool(const char* v) { this->Impl->brush["tool"] = v ? v : ""; }
void vtkPaintSurface::SetRadius(double v) { this->Impl->brush["radius"] = v; }
void vtkPaintSurface::SetStrength(double v) { this->Impl->brush["strength"] = v; }
void vtkPaintSurface::SetFalloff(const char* v) { this->Impl->brush["falloff"] = v ? v : ""; }
void vtkPaintSurface::SetSpacing(double v) { this->Impl->brush["spacing"] = v; }
void vtkPaintSurface::SetOp(const char* v) { this->Impl->brush["op"] = v ? v : ""; }
void vtkPaintSurface::SetAmount(double v) { this->Impl->brush["amount"] = v; }
void vtkPaintSurface::SetIterations(int v) { this->Impl->brush["iterations"] = v; }
void vtkPaintSurface::SetDiffuse(double r, double g, double b) { this->Impl->brush["channels"]["diffuse"] = {r, g, b}; }
void vtkPaintSurface::SetSpecular(double r, double g, double b) { this->Impl->brush["channels"]["specular"] = {r, g, b}; }
void vtkPaintSurface::SetRoughness(double v) { this->Impl->brush["channels"]["roughness"] = v; }
void vtkPaintSurface::SetDisplacement(double v) { this->Impl->brush["channels"]["displacement"] = v; }
void vtkPaintSurface::SetLabel(int v) { this->Impl->brush["channels"]["label"] = v; }
void vtkPaintSurface::SetMask(double v) { this->Impl->brush["channels"]["mask"] = v; }
void vtkPaintSurface::ClearChannels() { this->Impl->brush.erase("channels"); }

void vtkPaintSurface::SetEditLevel(int v)
{
  if (v > 0)
    this->Impl->brush["edit_level"] = v;
  else
    this->Impl->brush.erase("edit_level");
}

void vtkPaintSurface::SetSpace(const char* v) { this->Impl->brush["space"] = v ? v : ""; }
void vtkPaintSurface::SetBackfaces(const char* v) { this->Impl->brush["backfaces"] = v ? v : ""; }
void vtkPaintSurface::SetSide(const char* v) { this->Impl->brush["side"] = v ? v : ""; }

void vtkPaintSurface::SetCamera(double px, double py, double pz, double fx, double fy, double fz, double ux,
                                double uy, double uz, double view_angle)
{
  this->Impl->brush["camera"] = {{"position", {px, py, pz}},
                                 {"focal_point", {fx, fy, fz}},
                                 {"view_up", {ux, uy, uz}},
                                 {"view_angle", view_angle}};
}

void vtkPaintSurface::SetSpray(int drops, double size, int seed)
{
  if (drops > 0)
    this->Impl->brush["spray"] = {{"drops", drops}, {"size", size}, {"seed", seed}};
  else
    this->Impl->brush.erase("spray");
}

void vtkPaintSurface::SetMirror(const char* v)
{
  if (v && *v)
    this->Impl->brush["mirror"] = v;
  else
    this->Impl->brush.erase("mirror");
}

const char* vtkPaintSurface::GetBrushJSON()
{
  this->Impl->brush_text = this->Impl->brush.dump();
  return this->Impl->brush_text.c_str();
}

int vtkPaintSurface::ApplyStroke(vtkPoints* path)
{
  nlohmann::json stroke = this->Impl->brush;
  const std::string tool = stroke.value("tool", "paint");
  if (tool != "wash" && tool != "dip") {
    stroke["points"] = nlohmann::json::array();
    for (vtkIdType k = 0; path && k < path->GetNumberOfPoints(); ++k) {
      double p[3];
      path->GetPoint(k, p);
      stroke["points"].push_back({p[0], p[1], p[2]});
    }
  }
  // Settings of other tools stay in the brush for later; this stroke has
  // only the keys its own tool reads.
  stroke = nlohmann::json::parse(meshpaint::drop_meaningless_keys(stroke.dump()));
  return this->ApplyStrokes(nlohmann::json{{"strokes", {stroke}}}.dump().c_str());
}

int vtkPaintSurface::ApplyStrokes(const char* json)
{
  const int ok = meshpaint::guarded(this->LastError, [&] {
    meshpaint::StrokeScript script = meshpaint::parse_stroke_script(json ? json : "");
    meshpaint::load_stroke_rasters(script);
    if (script.level > 0) {
      // A level already chosen is never overridden by a script.
      const bool chosen = this->LevelSet || this->Impl->surface || !this->Impl->queued.empty();
      if (chosen && script.level != this->Level)
        throw meshpaint::InputError("the script's \"level\" " + std::to_string(script.level) +
                                    " conflicts with the painting level " + std::to_string(this->Level) +
                                    (this->LevelSet ? " (SetLevel or the loaded project)" : " (of the strokes before)"));
      if (!chosen && this->Level != script.level) {
        this->Level = script.level;
        this->Modified();
      }
    }
    for (auto& s : script.strokes)
      this->Impl->queued.push_back(std::move(s));
  });
  if (ok)
    this->Modified();
  return ok;
}

void vtkPaintSurface::SetLevel(int level)
{
  if (level < 1 || level > meshpaint::kMaxLevel) {
    this->LastError = "the painting level must be from 1 to " + std::to_string(meshpaint::kMaxLevel) + ", not " +
                      std::to_string(level);
    vtkErrorMacro(<< this->LastError);
    return;
  }
  this->LevelSet = true;
  if (level != this->Level) {
    this->Level = level;
    this->Modified();
  }
}

void vtkPaintSurface::SetModelLevel(int level)
{
  if (level < 0 || level > meshpaint::kMaxLevel) {
    this->LastError = "the model level must be from 0 (automatic) to " + std::to_string(meshpaint::kMaxLevel) +
                      ", not " + std::to_string(level);
    vtkErrorMacro(<< this->LastError);
    return;
  }
  if (level != this->ModelLevel) {
    this->ModelLevel = level;
    this->Modified();
  }
}

int vtkPaintSurface::Step(bool back)
{
  if (!this->Impl->surface) {
    this->LastError = "nothing painted yet";
    return 0;
  }
  bool done = false;
  const int ok = meshpaint::guarded(this->LastError, [&] {
    done = back ? this->Impl->session.undo() : this->Impl->session.redo();
  });
  if (ok && !done)
    this->LastError = back ? "nothing to undo" : "nothing to redo";
  if (!ok || !done)
    return 0;
  this->StrokeCount += back ? -1 : 1;
  this->Modified();
  return 1;
}

int vtkPaintSurface::Undo() { return this->Step(true); }

int vtkPaintSurface::Redo() { return this->Step(false); }

int vtkPaintSurface::FillInputPortInformation(int port, vtkInformation* info)
{
  // A loaded project takes the input's place.
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return this->Superclass::FillInputPortInformation(port, info);
}

int vtkPaintSurface::Ready()
{
  if (this->Impl->surface && this->Impl->queued.empty() && this->GetNumberOfInputConnections(0) == 0)
    return 1;
  const int failed = this->FailedUpdates;
  this->Update();
  if (this->FailedUpdates != failed)
    return 0;
  if (!this->Impl->surface) {
    this->LastError = "nothing to paint on: set an input or load a project";
    return 0;
  }
  return 1;
}

int vtkPaintSurface::SaveProject(const char* path)
{
  if (!this->Ready())
    return 0;
  return meshpaint::guarded(this->LastError, [&] {
    Internals& in = *this->Impl;
    meshpaint::Project base = in.project ? *in.project : meshpaint::Project();
    base.labels = in.labels;
    base.origin = in.origin;
    in.origin = meshpaint::save_painted_project(*in.surface, std::move(base), path ? path : "");
  });
}

const char* vtkPaintSurface::GetHistoryJSON()
{
  Internals& in = *this->Impl;
  in.history_text.clear();
  if (in.surface)
    meshpaint::guarded(this->LastError, [&] {
      in.history_text = meshpaint::continued_history(in.project ? in.project->history : "", in.surface->history(),
                                                     in.surface->level());
    });
  return in.history_text.c_str();
}

int vtkPaintSurface::LoadProject(const char* path)
{
  const int ok = meshpaint::guarded(this->LastError, [&] {
    meshpaint::Project p = meshpaint::load_project(path ? path : "");
    auto runtime = meshpaint::Runtime::open(this->Device);
    auto surface = meshpaint::open_project_surface(runtime, p, meshpaint::default_storage(runtime->info()));
    Internals& in = *this->Impl;
    this->RemoveAllInputConnections(0);
    in.set_surface(std::move(surface));
    in.queued.clear();
    in.built_from = 0;
    in.built_level = p.level;
    this->ImportReport.clear();
    this->Level = p.level;
    this->LevelSet = true;
    this->StrokeCount = 0;
    // Only what the next save carries over; the layers live in the surface.
    p.positions = {};
    p.channels = {};
    in.origin = p.origin;
    in.labels = p.labels;
    in.project = std::move(p);
  });
  if (ok)
    this->Modified();
  return ok;
}

int vtkPaintSurface::ExportModel(const char* dir)
{
  if (!this->Ready())
    return 0;
  return meshpaint::guarded(this->LastError, [&] {
    const int level = this->Impl->surface->level();
    const int model_level =
      this->ModelLevel > 0 ? std::min(this->ModelLevel, level) : meshpaint::default_model_level(level);
    const Internals& in = *this->Impl;
    meshpaint::export_painting(*in.surface, model_level, dir ? dir : "", in.labels);
  });
}

int vtkPaintSurface::AddImportArray(const char* name, const char* channel)
{
  const int ok = meshpaint::guarded(this->LastError, [&] {
    this->Impl->imports.push_back(
      meshpaint::parse_array_import(std::string(name ? name : "") + ":" + (channel ? channel : "")));
    this->Impl->imports_changed = true;
  });
  if (ok)
    this->Modified();
  return ok;
}

void vtkPaintSurface::RemoveAllImportArrays()
{
  this->Impl->imports.clear();
  this->Impl->imports_changed = true;
  this->Modified();
}

int vtkPaintSurface::GetNumberOfLabelClasses()
{
  return int(this->Impl->labels.size());
}

int vtkPaintSurface::GetLabelClassId(int i)
{
  const auto& labels = this->Impl->labels;
  return i >= 0 && i < int(labels.size()) ? labels[std::size_t(i)].id : -1;
}

const char* vtkPaintSurface::GetLabelClassName(int i)
{
  const auto& labels = this->Impl->labels;
  return i >= 0 && i < int(labels.size()) ? labels[std::size_t(i)].name.c_str() : "";
}

void vtkPaintSurface::GetLabelClassColor(int i, double rgb[3])
{
  const auto& labels = this->Impl->labels;
  for (int a = 0; a < 3; ++a)
    rgb[a] = i >= 0 && i < int(labels.size()) ? double(labels[std::size_t(i)].colour[std::size_t(a)]) : 0.0;
}

vtkDataArray* vtkPaintSurface::GetChannel(const char* name)
{
  if (!this->Ready())
    return nullptr;
  const std::string channel = name ? name : "";
  vtkSmartPointer<vtkDataArray> array;
  const int ok = meshpaint::guarded(this->LastError, [&] {
    const std::vector<float> values = meshpaint::vertex_channel(*this->Impl->surface, channel);
    const int k = meshpaint::channel_components(channel);
    if (channel == "label")
      array = vtkSmartPointer<vtkIntArray>::New();
    else
      array = vtkSmartPointer<vtkFloatArray>::New();
    array->SetName(channel.c_str());
    array->SetNumberOfComponents(k);
    array->SetNumberOfTuples(vtkIdType(values.size() / std::size_t(k)));
    for (std::size_t v = 0; v < values.size(); ++v)
      array->SetComponent(vtkIdType(v / std::size_t(k)), int(v % std::size_t(k)), values[v]);
  });
  if (!ok)
    return nullptr;
  this->Impl->channels[channel] = array;
  return array;
}

int vtkPaintSurface::SetChannel(const char* name, vtkDataArray* values)
{
  if (!this->Ready())
    return 0;
  const int ok = meshpaint::guarded(this->LastError, [&] {
    const std::string channel = name ? name : "";
    const int k = meshpaint::channel_components(channel);
    if (!values)
      throw meshpaint::InputError("SetChannel needs an array");
    if (values->GetNumberOfComponents() != k)
      throw meshpaint::InputError("channel '" + channel + "' has " + std::to_string(k) + " component" +
                                  (k > 1 ? "s" : "") + ", the array " +
                                  std::to_string(values->GetNumberOfComponents()));
    std::vector<float> v(std::size_t(values->GetNumberOfTuples()) * std::size_t(k));
    for (std::size_t i = 0; i < v.size(); ++i)
      v[i] = float(values->GetComponent(vtkIdType(i / std::size_t(k)), int(i % std::size_t(k))));
    meshpaint::set_vertex_channel(*this->Impl->surface, channel, v);
  });
  if (ok)
    this->Modified();
  return ok;
}

int vtkPaintSurface::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                 vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  const int ok = meshpaint::guarded(this->LastError, [&] {
    Internals& in = *this->Impl;
    // A new input or level starts a new surface; queued strokes go onto it.
    // Without an input, the surface is a loaded project's.
    if (!input && !in.surface)
      throw meshpaint::InputError("nothing to paint on: set an input or load a project");
    if (!in.surface ||
        (input && (in.built_from != input->GetMTime() || in.built_welded != this->Weld || in.imports_changed)) ||
        in.built_level != this->Level) {
      if (!input)
        throw meshpaint::InputError("a loaded project keeps its level " + std::to_string(in.built_level) +
                                    "; set an input to paint at another");
      meshpaint::ImportOptions import;
      import.weld = this->Weld;
      import.arrays = in.imports;
      const meshpaint::BaseMesh mesh = meshpaint::import_polydata(input, "input", "input polygons: ", import);
      std::string report;
      for (const auto& lines : {mesh.report.step_lines("the polydata", "WeldOff()"), mesh.report.lines()})
        for (const std::string& line : lines)
          report += (report.empty() ? "" : "\n") + line;
      auto runtime = meshpaint::Runtime::open(this->Device);
      auto surface =
        std::make_shared<meshpaint::PaintSurface>(runtime, mesh, this->Level, meshpaint::default_storage(runtime->info()));
      meshpaint::apply_imported_channels(*surface);
      meshpaint::apply_imported_labels(*surface);
      in.set_surface(std::move(surface));
      in.labels = meshpaint::imported_label_classes(mesh);
      this->ImportReport = report;
      in.built_from = input->GetMTime();
      in.built_level = this->Level;
      in.built_welded = this->Weld;
      in.imports_changed = false;
      in.project.reset();
      in.origin = {};
      this->StrokeCount = 0;
    }
    for (const meshpaint::Stroke& s : in.queued) {
      const std::size_t depth = in.surface->undo_log().undo_depth();
      try {
        in.session.apply(s);
      } catch (...) {
        // A stroke that failed halfway is still one undo step.
        if (in.surface->undo_log().undo_depth() > depth)
          ++this->StrokeCount;
        throw;
      }
      ++this->StrokeCount;
    }
    in.queued.clear();
    this->SharingArrays = false;
    const auto shared = this->ShareArrays ? in.surface->display_arrays() : nullptr;
    if (!shared) {
      in.shared = nullptr;
      output->ShallowCopy(meshpaint::to_polydata(in.surface->painted_surface()));
      return;
    }
    if (!in.shared || in.shared_from.lock() != in.surface) {
      in.shared = meshpaint::to_polydata(in.surface->painted_surface());
      meshpaint::share_arrays(in.shared, shared);
      in.shared_from = in.surface;
      in.shared_seen.clear();
      for (std::size_t k = 0; k < shared->arrays().size(); ++k)
        in.shared_seen.push_back(shared->version(k));
    } else {
      meshpaint::refresh_shared_arrays(in.shared, shared, in.shared_seen);
    }
    output->ShallowCopy(in.shared);
    this->SharingArrays = true;
  });
  if (!ok) {
    ++this->FailedUpdates;
    vtkErrorMacro(<< this->LastError);
    this->Impl->queued.clear();
  }
  return ok;
}

std::shared_ptr<meshpaint::PaintSurface> vtkPaintSurface::GetPaintSurface()
{
  return this->Impl->surface;
}

const meshpaint::Project* vtkPaintSurface::GetProject() const
{
  return this->Impl->project ? &*this->Impl->project : nullptr;
}

void vtkPaintSurface::ViewPainted()
{
  if (this->Impl->surface)
    this->StrokeCount = int(this->Impl->surface->history().size());
  this->Modified();
}
