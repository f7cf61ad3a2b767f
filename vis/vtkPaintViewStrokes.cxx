// vtkPaintView's strokes: scripts applied, the stroke drawn with the mouse
// (painted piece by piece for the eye, applied whole at release), undo and
// redo, and the recording.
#include "vtkPaintView.h"
#include "vtkPaintViewInternals.h"

#include "CallGuard.h" // for meshpaint::guarded
#include "RasterIO.h"  // for meshpaint::load_stroke_rasters

#include "core/errors.h"  // for meshpaint::InputError
#include "paint/stroke.h" // for meshpaint::parse_stroke_script, stroke_script_json

#include <vtkCamera.h> // for vtkCamera

#include <cmath> // for std::sqrt

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
