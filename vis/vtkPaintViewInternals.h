// The state vtkPaintView's files share: the scene, how it is drawn, the
// window's parts and the running stroke. Private to vtkPaintView*.cxx.
#ifndef vtkPaintViewInternals_h
#define vtkPaintViewInternals_h

#include "vtkPaintView.h"

#include "BrushCursor.h"             // for meshpaint::BrushCursor
#include "BrushSettings.h"           // for meshpaint::BrushSettings
#include "ChannelDisplay.h"          // for meshpaint::ShownChannel
#include "ChannelLegend.h"           // for meshpaint::ChannelLegend
#include "LevelOfDetail.h"           // for meshpaint::FrameTiming
#include "PaintControls.h"           // for meshpaint::PaintControls
#include "SceneDrawing.h"            // for meshpaint::ObjectDrawing
#include "ViewText.h"                // for meshpaint::ViewText
#include "vtkPaintInteractorStyle.h" // for vtkPaintInteractorStyle

#include "core/vec.h"          // for meshpaint::Vec3
#include "paint/paint_scene.h"    // for meshpaint::PaintScene
#include "paint/stroke_session.h" // for meshpaint::StrokeSession
#include "project/project.h"   // for meshpaint::Project

#include <vtkNew.h>                    // for vtkNew
#include <vtkRenderWindow.h>           // for vtkRenderWindow
#include <vtkRenderWindowInteractor.h> // for vtkRenderWindowInteractor
#include <vtkRenderer.h>               // for vtkRenderer
#include <vtkSmartPointer.h>           // for vtkSmartPointer

#include <memory> // for std::unique_ptr
#include <string> // for std::string
#include <vector> // for std::vector

//! What the interactor style's events ask of the view, as calls on its
//! public methods.
class vtkPaintViewControls : public meshpaint::PaintControls
{
public:
  explicit vtkPaintViewControls(vtkPaintView* view) : view_(view) {}
  bool begin_stroke(int x, int y) override { return view_->BeginStroke(x, y) != 0; }
  void continue_stroke(int x, int y) override { view_->ContinueStroke(x, y); }
  void end_stroke() override { view_->EndStroke(); }
  bool painting() const override { return view_->IsPainting(); }
  void hover(int x, int y) override { view_->MoveCursor(x, y); }
  void key(const std::string& keysym, bool control, bool shift) override
  {
    view_->HandleKey(keysym.c_str(), control, shift);
  }
  void camera_moving(bool moving) override { view_->SetMoving(moving); }

private:
  vtkPaintView* view_;
};

struct vtkPaintView::Internals
{
  explicit Internals(vtkPaintView* view) : controls(view) {}

  vtkPaintViewControls controls; // first: it outlives the style that calls it
  meshpaint::PaintScene scene;
  meshpaint::StrokeSession session{scene}; // every stroke, drawn or scripted, goes through it
  std::vector<std::unique_ptr<meshpaint::ObjectDrawing>> drawings; // one per object, in the scene's order
  std::unique_ptr<meshpaint::Project> project; // where the first object came from, if from a project
  meshpaint::ProjectOrigin origin;             // the project file last loaded or saved, as it was then
  std::unique_ptr<meshpaint::BrushSettings> brush;
  bool lit = false;    // drawn with the subsurface light
  meshpaint::ShownChannel shown = meshpaint::ShownChannel::diffuse;
  bool channel_drawn = false; // the actors draw another channel than the materials
  std::vector<meshpaint::LabelClass> labels; // the classes the label channel shows
  std::vector<int> hidden_labels;            // class ids shown as unlabelled
  bool moving = false; // the camera turns or a stroke is drawn
  int shown_level = 0;
  meshpaint::FrameTiming timing; // of frames at rest, for the automatic level of detail
  vtkNew<vtkRenderer> renderer;
  // The view's own window and interactor, or those of a widget that hosts
  // the view (SetRenderWindow()).
  vtkSmartPointer<vtkRenderWindow> window = vtkSmartPointer<vtkRenderWindow>::New();
  vtkSmartPointer<vtkRenderWindowInteractor> interactor = vtkSmartPointer<vtkRenderWindowInteractor>::New();
  bool hosted = false; // the window is a widget's: its size and event loop are the widget's
  double step_ms = 0;  // the last brush step: the dabs of one new point of a stroke
  vtkNew<vtkPaintInteractorStyle> style;
  meshpaint::BrushCursor cursor;
  meshpaint::ViewText text;
  meshpaint::ChannelLegend legend; // colour bar or label classes of the channel shown
  bool initialized = false;
  // The stroke being drawn (its path is the session's).
  bool painting = false;
  bool ended = false; // reached a silhouette or left the surface
  std::string recording;
};

#endif
