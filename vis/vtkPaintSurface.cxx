#include "vtkPaintSurface.h"

#include "RasterIO.h"          // for meshpaint::load_stroke_rasters
#include "SurfaceConversion.h" // for meshpaint::to_base_mesh, to_polydata

#include "paint/paint_surface.h" // for meshpaint::PaintSurface

#include <nlohmann/json.hpp> // for nlohmann::json

#include <vtkInformation.h>       // for vtkInformation
#include <vtkInformationVector.h> // for vtkInformationVector
#include <vtkObjectFactory.h>     // for vtkStandardNewMacro
#include <vtkPoints.h>            // for vtkPoints
#include <vtkPolyData.h>          // for vtkPolyData

#include <vector> // for std::vector

vtkStandardNewMacro(vtkPaintSurface);

struct vtkPaintSurface::Internals
{
  nlohmann::json brush = {{"tool", "paint"}}; // the setters' stroke, without points
  std::string brush_text;
  std::unique_ptr<meshpaint::PaintSurface> surface;
  vtkMTimeType built_from = 0; // input's modification time the surface was built from
  int built_level = 0;
  std::vector<meshpaint::Stroke> queued;
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

namespace {

//! Runs `f`, keeping any exception's message in `error`; 1 on success.
template <typename F>
int guarded(std::string& error, F&& f)
{
  error.clear();
  try {
    f();
    return 1;
  } catch (const cl::Error& e) {
    error = meshpaint::describe(e);
  } catch (const std::exception& e) {
    error = e.what();
  }
  return 0;
}

} // namespace

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
  const int ok = guarded(this->LastError, [&] {
    meshpaint::StrokeScript script = meshpaint::parse_stroke_script(json ? json : "");
    meshpaint::load_stroke_rasters(script);
    if (script.level > 0 && !this->Impl->surface && this->Impl->queued.empty())
      this->SetLevel(script.level);
    for (auto& s : script.strokes)
      this->Impl->queued.push_back(std::move(s));
  });
  if (ok)
    this->Modified();
  return ok;
}

int vtkPaintSurface::Step(bool back)
{
  if (!this->Impl->surface) {
    this->LastError = "nothing painted yet";
    return 0;
  }
  bool done = false;
  const int ok = guarded(this->LastError, [&] {
    done = back ? this->Impl->surface->undo() : this->Impl->surface->redo();
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

int vtkPaintSurface::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                 vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  const int ok = guarded(this->LastError, [&] {
    Internals& in = *this->Impl;
    // A new input or level starts a new surface; queued strokes go onto it.
    if (!in.surface || in.built_from != input->GetMTime() || in.built_level != this->Level) {
      auto runtime = meshpaint::Runtime::open(this->Device);
      in.surface = std::make_unique<meshpaint::PaintSurface>(runtime, meshpaint::to_base_mesh(input, "input"),
                                                             this->Level, meshpaint::default_storage(runtime->info()));
      in.built_from = input->GetMTime();
      in.built_level = this->Level;
      this->StrokeCount = 0;
    }
    for (const meshpaint::Stroke& s : in.queued) {
      const std::size_t depth = in.surface->undo_log().undo_depth();
      try {
        in.surface->apply(s);
      } catch (...) {
        // A stroke that failed halfway is still one undo step.
        if (in.surface->undo_log().undo_depth() > depth)
          ++this->StrokeCount;
        throw;
      }
      ++this->StrokeCount;
    }
    in.queued.clear();
    output->ShallowCopy(meshpaint::to_polydata(in.surface->painted_surface()));
  });
  if (!ok) {
    ++this->FailedUpdates;
    vtkErrorMacro(<< this->LastError);
    this->Impl->queued.clear();
  }
  return ok;
}
