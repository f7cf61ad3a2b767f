// meshpaint bench view --studio: the studio's own frames while painting: the
// painting view inside StudioWindow, driven by Qt mouse events, each frame
// timed from the mouse event to the end of the frame Qt's widget drew.

#include "benchmarks.h"
#include "table.h"

#include "DisplayCheck.h"
#include "Studio.h"
#include "StudioWindow.h"
#include "vtkPaintView.h"

#include "core/errors.h"
#include "core/format.h"
#include "core/timer.h"

#include <QApplication>             // for QApplication
#include <QMouseEvent>              // for QMouseEvent
#include <QVTKOpenGLNativeWidget.h> // for QVTKOpenGLNativeWidget

#include <vtkCamera.h>       // for vtkCamera
#include <vtkCommand.h>      // for vtkCommand
#include <vtkRenderWindow.h> // for vtkRenderWindow
#include <vtkRenderer.h>     // for vtkRenderer
#include <vtkSmartPointer.h> // for vtkSmartPointer

#include <iostream> // for std::cout
#include <memory>   // for std::unique_ptr

namespace meshpaint::cli {
namespace {

constexpr int kWidth = 800, kHeight = 600;

//! Counts the frames the widget's render window finishes.
struct FrameCounter
{
  int frames = 0;
  void ended() { ++frames; }
};

//! Runs Qt's events until the window has drawn a frame more than `before`.
void wait_for_frame(FrameCounter& counter, int before)
{
  Timer waited;
  while (counter.frames == before && waited.ms() < 60000)
    QApplication::processEvents(QEventLoop::AllEvents, 5);
}

void send_mouse(QWidget* w, QEvent::Type type, int x, int y, Qt::MouseButton button, Qt::MouseButtons held)
{
  QMouseEvent e(type, QPointF(x, y), w->mapToGlobal(QPoint(x, y)), button, held, Qt::NoModifier);
  QApplication::sendEvent(w, &e);
}

//! Median time of one step of a left-drag across the middle of the view:
//! the mouse event, the brush step, the display update and Qt's frame.
double studio_paint_ms(QWidget* widget, FrameCounter& counter, int steps)
{
  const int y = widget->height() / 2;
  int x = widget->width() / 2 - 2 * steps;
  send_mouse(widget, QEvent::MouseMove, x, y, Qt::NoButton, Qt::NoButton);
  wait_for_frame(counter, counter.frames);
  send_mouse(widget, QEvent::MouseButtonPress, x, y, Qt::LeftButton, Qt::LeftButton);
  QApplication::processEvents();
  std::vector<double> t;
  for (int k = 0; k < steps; ++k) {
    x += 4;
    const int before = counter.frames;
    Timer frame;
    send_mouse(widget, QEvent::MouseMove, x, y, Qt::NoButton, Qt::LeftButton);
    wait_for_frame(counter, before);
    t.push_back(frame.ms());
  }
  send_mouse(widget, QEvent::MouseButtonRelease, x, y, Qt::LeftButton, Qt::NoButton);
  wait_for_frame(counter, counter.frames); // the full level again, at rest
  return median(t);
}

//! Median time of a frame after a small turn of the camera, `moving` as
//! while the camera is dragged (level of detail) or at rest.
double studio_render_ms(vtkPaintView* view, FrameCounter& counter, int steps, bool moving)
{
  view->SetMoving(moving);
  std::vector<double> t;
  for (int k = 0; k < steps; ++k) {
    view->GetRenderer()->GetActiveCamera()->Azimuth(k % 2 ? -1.0 : 1.0);
    const int before = counter.frames;
    Timer frame;
    view->Render();
    wait_for_frame(counter, before);
    t.push_back(frame.ms());
  }
  view->SetMoving(false);
  return median(t);
}

} // namespace

int bench_view_studio(const Args& args)
{
  const int steps = args.integer("--steps", 7, 1, 1000);
  require_display(); // VTK and Qt abort without one
  open_device(args); // a bad --device fails here, before the window
  studio::prepare_qt();
  static int argc = 1;
  static char name[] = "meshpaint-bench";
  static char* argv[] = {name, nullptr};
  QApplication app(argc, argv);
  struct Row
  {
    std::string mesh;
    int level;
  };
  // The rows of bench view: about 100k, 600k and 2.5M faces.
  const Row rows[] = {{"femur.off", 2}, {"armadillo.off", 2}, {"armadillo.off", 3}};
  Table table({"faces", "mesh", "LoD level", "paint frame ms", "paint fps", "paint frame LoD ms", "paint fps LoD",
               "render ms", "render LoD ms"});
  for (const Row& row : rows) {
    vtkSmartPointer<vtkPaintView> view = vtkSmartPointer<vtkPaintView>::New();
    view->SetLevel(row.level);
    view->SetDevice(args.value("--device").c_str());
    view->SetStorage(args.value("--storage").c_str());
    view->SetSize(kWidth, kHeight);
    if (!view->LoadMesh((scans_dir() + "/" + row.mesh).c_str()))
      throw DeviceError(view->GetLastError());
    auto window = std::make_unique<studio::StudioWindow>(view);
    if (!window->ready())
      throw DeviceError(window->error().toStdString());
    window->show();
    QWidget* widget = window->render_widget();
    // The view's widget at the size of bench view's offscreen window.
    for (int k = 0; k < 3; ++k) {
      window->resize(window->width() + kWidth - widget->width(), window->height() + kHeight - widget->height());
      QApplication::processEvents();
    }
    FrameCounter counter;
    const unsigned long observer =
      view->GetRenderWindow()->AddObserver(vtkCommand::EndEvent, &counter, &FrameCounter::ended);
    view->Render();
    wait_for_frame(counter, 0);
    const double full_render = studio_render_ms(view, counter, steps, false);
    const double lod_render = studio_render_ms(view, counter, steps, true);
    const int lod_level = view->GetLodLevelInUse();
    view->SetLodLevel(0);
    const double frame = studio_paint_ms(widget, counter, steps);
    view->SetLodLevel(-1);
    const double frame_lod = studio_paint_ms(widget, counter, steps);
    view->GetRenderWindow()->RemoveObserver(observer);
    const std::string name = row.mesh.substr(0, row.mesh.find('.')) + " L" + std::to_string(row.level);
    table.add({grouped((unsigned long long)view->GetFaceCount()), name, std::to_string(lod_level), format_fixed(frame, 1),
               format_fixed(1000.0 / frame, 1), format_fixed(frame_lod, 1), format_fixed(1000.0 / frame_lod, 1),
               format_fixed(full_render, 1), format_fixed(lod_render, 1)});
    window.reset(); // one window at a time
  }
  std::cout << "meshpaint bench view --studio: the studio's view at " << kWidth << "x" << kHeight
            << ", median of " << steps << " frames; a paint frame runs from the Qt mouse event of one step of a\n"
            << "drag to the end of the frame the widget drew (brush step, display update, render); LoD: the level\n"
            << "chosen for 10 frames per second while painting or moving\n\n";
  table.print(std::cout);
  return 0;
}

} // namespace meshpaint::cli
