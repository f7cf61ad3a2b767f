// vtkPaintView's strokes, all through the scene's StrokeSession: scripts
// applied, the stroke drawn with the mouse (painted once, as its path grows),
// the fill and the eyedropper at a pixel, undo and redo, and the recording.
#include "vtkPaintView.h"
#include "vtkPaintViewInternals.h"

#include "CallGuard.h" // for meshpaint::guarded
#include "RasterIO.h"  // for meshpaint::load_stroke_rasters
#include "vtkSurfacePicker.h" // for vtkSurfacePicker

#include "core/errors.h"  // for meshpaint::InputError
#include "core/format.h"  // for meshpaint::format_fixed
#include "paint/paint_surface.h" // for meshpaint::PaintSurface, PaintedVertices
#include "paint/stroke.h" // for meshpaint::parse_stroke_script, stroke_script_json

#include <vtkCamera.h> // for vtkCamera

#include <chrono> // for std::chrono::steady_clock

// The picker knows the patch and (u, v) under the cursor: the dab's search
// for its centre starts there instead of at the brush radius.
void vtkPaintView::HintSnap()
{
  Internals& in = *this->Impl;
  vtkSurfacePicker* picker = in.cursor.picker();
  const int object = picker->GetActorIndex();
  if (object >= 0 && std::size_t(object) < in.scene.size() && picker->GetPatch() >= 0)
    in.scene.surface(std::size_t(object)).hint_snap(int(picker->GetPatch()), picker->GetU(), picker->GetV());
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
  if (this->RefusedWhileLocked())
    return 0;
  const int ok = meshpaint::guarded(this->LastError, [&] {
    if (in.scene.empty())
      throw meshpaint::InputError("no surface to paint: load a mesh first");
    for (const meshpaint::Stroke& s : script.strokes)
      in.session.apply(s);
  });
  const std::string error = this->LastError; // showing what was painted must not hide why it stopped
  this->Refresh(true);
  if (!ok)
    this->LastError = error;
  return ok;
}

int vtkPaintView::BeginStroke(int x, int y)
{
  Internals& in = *this->Impl;
  double p[3], n[3];
  if (in.painting || this->Locked || !this->PickFacing(x, y, p, n))
    return 0;
  for (std::size_t o = 0; o < in.scene.size(); ++o)
    in.scene.surface(o).undo_log().set_budget(std::size_t(this->UndoBudget * 1048576.0));
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
  const meshpaint::Vec3 at{float(p[0]), float(p[1]), float(p[2])};
  this->HintSnap();
  if (!meshpaint::guarded(this->LastError, [&] { in.session.begin(in.brush->stroke({at})); })) {
    this->Message = this->LastError;
    this->UpdateText();
    return 0;
  }
  in.painting = true;
  in.ended = false;
  in.moving = true;
  this->Refresh(false);
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
  const meshpaint::Vec3& last = in.session.current().points.back();
  // Points closer than half a dab spacing add nothing but cost.
  if (meshpaint::length(meshpaint::sub(q, last)) < 0.5 * in.brush->spacing() * in.brush->radius())
    return 1;
  bool on = true;
  const auto start = std::chrono::steady_clock::now();
  this->HintSnap();
  if (!meshpaint::guarded(this->LastError, [&] { on = in.session.extend(q); })) {
    on = false; // the session has closed the stroke; LastError says why, and EndStroke() again
    this->Message = this->LastError;
  }
  in.ended = !on;
  this->PlaceCursor(x, y);
  this->Refresh(false); // renders
  in.step_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return 1;
}

int vtkPaintView::EndStroke()
{
  Internals& in = *this->Impl;
  if (!in.painting)
    return 0;
  in.painting = false;
  in.moving = false;
  // A failure while drawing has closed the stroke and taken it back
  // already, and LastError says why: the renders since leave it (Show()).
  const int ok = in.session.drawing() && meshpaint::guarded(this->LastError, [&] { in.session.end(); });
  this->Message = ok ? "" : this->LastError;
  this->Refresh(true);
  return ok;
}

int vtkPaintView::FillAt(int x, int y)
{
  Internals& in = *this->Impl;
  double p[3], n[3];
  if (in.painting || !in.brush || !this->PickFacing(x, y, p, n))
    return 0;
  const meshpaint::Vec3 at{float(p[0]), float(p[1]), float(p[2])};
  const int ok = meshpaint::guarded(this->LastError, [&] { in.session.apply(in.brush->fill_stroke(at)); });
  this->Message = ok ? "filled with class " + std::to_string(in.brush->label()) : this->LastError;
  this->Refresh(true);
  return ok;
}

int vtkPaintView::PickAt(int x, int y)
{
  Internals& in = *this->Impl;
  double p[3], n[3];
  if (in.painting || !in.brush || !this->PickFacing(x, y, p, n))
    return 0;
  const int object = in.cursor.picker()->GetActorIndex();
  if (object < 0 || std::size_t(object) >= in.scene.size())
    return 0;
  return meshpaint::guarded(this->LastError, [&] {
    // The texel the brush would snap to, and its welded vertex's values.
    meshpaint::PaintSurface& surface = in.scene.surface(std::size_t(object));
    meshpaint::CullRecord closest{};
    const meshpaint::Vec3 at{float(p[0]), float(p[1]), float(p[2])};
    if (surface.brush_patches(at, float(in.brush->radius()), nullptr, nullptr, 0.f, &closest).empty())
      throw meshpaint::InputError("nothing to pick: no surface under the mouse");
    const meshpaint::PaintedVertices v = surface.painted_vertices({closest.patch});
    const meshpaint::Vec3 snapped{closest.closest_position[0], closest.closest_position[1], closest.closest_position[2]};
    std::size_t best = 0;
    for (std::size_t k = 1; k < v.ids.size(); ++k)
      if (meshpaint::length(meshpaint::sub(v.values.surface.points[k], snapped)) <
          meshpaint::length(meshpaint::sub(v.values.surface.points[best], snapped)))
        best = k;
    if (in.brush->tool() == "label") {
      in.brush->set_label(v.values.label[best]);
      this->Message = "picked class " + std::to_string(v.values.label[best]);
    } else {
      const meshpaint::Vec3& c = v.values.diffuse[best];
      in.brush->set_colour({c[0], c[1], c[2]});
      this->Message = "picked colour " + meshpaint::format_fixed(c[0], 2) + " " + meshpaint::format_fixed(c[1], 2) +
                      " " + meshpaint::format_fixed(c[2], 2);
    }
    this->UpdateText();
    this->Render();
  });
}

bool vtkPaintView::IsPainting() const { return this->Impl->painting; }

int vtkPaintView::Step(bool back)
{
  Internals& in = *this->Impl;
  if (this->RefusedWhileLocked())
    return 0;
  bool done = false;
  const int ok = !in.scene.empty() && meshpaint::guarded(this->LastError, [&] {
    done = back ? in.session.undo() : in.session.redo();
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
  in.recording = meshpaint::stroke_script_json(in.session.recording(this->Level));
  return in.recording.c_str();
}
