// meshpaint bench view: the window's frame time while painting (brush step,
// display update and render), with and without level of detail, the time to
// draw a frame alone, and pick latency, offscreen at 800x600.

#include "benchmarks.h"
#include "progress_bar.h"
#include "table.h"

#include "DisplayCheck.h"
#include "vtkPaintView.h"
#include "vtkSurfacePicker.h"

#include "core/errors.h"
#include "core/format.h"
#include "core/timer.h"

#include <vtkCamera.h>       // for vtkCamera
#include <vtkNew.h>          // for vtkNew
#include <vtkRenderWindow.h> // for vtkRenderWindow::ReportCapabilities
#include <vtkRenderer.h>     // for vtkRenderer
#include <vtkSmartPointer.h> // for vtkSmartPointer

#include <iostream> // for std::cout
#include <sstream>  // for std::istringstream

namespace meshpaint::cli {
namespace {

struct ViewRow
{
  std::string mesh;
  int level;
};

// The meshes and levels of bench paint: about 100k, 600k and 2.3M faces.
const ViewRow kViewRows[] = {{"femur.off", 2}, {"armadillo.off", 2}, {"armadillo.off", 3}};
constexpr int kWidth = 800, kHeight = 600;

//! Median time of one step of a drag across the middle of the window: the
//! brush step, the display update and the render.
double stroke_frame_ms(vtkPaintView* view, int steps)
{
  const int y = kHeight / 2;
  int x = kWidth / 2 - 2 * steps;
  if (!view->BeginStroke(x, y))
    throw InputError("bench view: no surface at the centre of the window");
  std::vector<double> t;
  for (int k = 0; k < steps; ++k) {
    x += 4;
    Timer frame;
    view->ContinueStroke(x, y);
    t.push_back(frame.ms());
  }
  view->EndStroke();
  return median(t);
}

//! Median time to draw a frame after a small turn of the camera.
double render_ms(vtkPaintView* view, int steps)
{
  std::vector<double> t;
  for (int k = 0; k < steps; ++k) {
    view->GetRenderer()->GetActiveCamera()->Azimuth(k % 2 ? -1.0 : 1.0);
    Timer frame;
    view->Render();
    t.push_back(frame.ms());
  }
  return median(t);
}

//! The OpenGL renderer that draws the window (llvmpipe, a GPU...), as the
//! driver names it; frame times mean little without it.
std::string gl_renderer(vtkPaintView* view)
{
  std::istringstream report(view->GetRenderWindow()->ReportCapabilities());
  const std::string key = "OpenGL renderer string:";
  for (std::string line; std::getline(report, line);)
    if (line.compare(0, key.size(), key) == 0)
      return line.substr(line.find_first_not_of(' ', key.size()));
  return "unknown";
}

} // namespace

int bench_view(const Args& args)
{
  args.expect_positionals(1, 1, "view [--steps N] [--quiet]");
  const int steps = args.integer("--steps", 7, 1, 1000);
  require_display(); // VTK and Qt abort without one
  open_device(args); // a bad --device fails here, before the window
  std::string renderer;
  Table table({"faces", "mesh", "LoD level", "paint frame ms", "paint frame LoD ms", "LoD, read back ms",
               "render ms", "render LoD ms", "capture ms", "pick ms"});
  ProgressBar bar("meshpaint bench", args.flag("--quiet"));
  ProgressTask task(&bar, "view on " + std::to_string(std::size(kViewRows)) + " meshes", std::size(kViewRows));
  std::size_t row_done = 0;
  for (const ViewRow& row : kViewRows) {
    const auto open_view = [&](bool share) {
      vtkSmartPointer<vtkPaintView> view = vtkSmartPointer<vtkPaintView>::New();
      view->SetShareArrays(share);
      view->SetLevel(row.level);
      view->SetDevice(args.value("--device").c_str());
      view->SetStorage(args.value("--storage").c_str());
      view->SetSize(kWidth, kHeight);
      view->OffScreenOn();
      if (!view->LoadMesh((scans_dir() + "/" + row.mesh).c_str()) || !view->Initialize())
        throw DeviceError(view->GetLastError());
      return view;
    };
    vtkSmartPointer<vtkPaintView> view = open_view(true);
    // At rest, full level: drawing and the item buffer.
    const double full_render = render_ms(view, steps);
    renderer = gl_renderer(view);
    std::vector<double> capture, pick;
    for (int k = 0; k < steps; ++k) {
      Timer c;
      view->GetPicker()->Capture();
      capture.push_back(c.ms());
    }
    for (int k = 0; k < 100; ++k) {
      Timer p;
      view->GetPicker()->Pick(kWidth / 2 + k % 10, kHeight / 2 + k / 10);
      pick.push_back(p.ms());
    }
    view->SetMoving(true);
    const double lod_render = render_ms(view, steps);
    view->SetMoving(false);
    const int lod_level = view->GetLodLevelInUse();
    view->SetLodLevel(0);
    const double frame = stroke_frame_ms(view, steps);
    view->SetLodLevel(-1);
    const double frame_lod = stroke_frame_ms(view, steps);
    // The same with the changed vertices read back into VTK's own arrays,
    // as where the device's memory is not the host's.
    std::string frame_copy = "-";
    if (view->IsSharingArrays()) {
      view = nullptr; // one window at a time
      vtkSmartPointer<vtkPaintView> copying = open_view(false);
      render_ms(copying, steps); // the rate the automatic level of detail goes by
      frame_copy = format_fixed(stroke_frame_ms(copying, steps), 1);
      view = copying;
    }
    const std::string name = row.mesh.substr(0, row.mesh.find('.')) + " L" + std::to_string(row.level);
    table.add({grouped((unsigned long long)view->GetFaceCount()), name, std::to_string(lod_level), format_fixed(frame, 1),
               format_fixed(frame_lod, 1), frame_copy, format_fixed(full_render, 1), format_fixed(lod_render, 1),
               format_fixed(median(capture), 1), format_fixed(median(pick), 3)});
    task.step(++row_done);
  }
  std::cout << "meshpaint bench view: offscreen " << kWidth << "x" << kHeight << " drawn by " << renderer
            << ", median of " << steps << " frames; a paint frame is one step of a drag (brush step, display update, render);\n"
            << "LoD draws the level chosen for 10 frames per second while painting or moving; the paint frames draw from\n"
            << "the engine's arrays in place where its device memory is the host's, \"read back\" copies the changed vertices\n"
            << "into VTK's arrays instead; pick: one item-buffer look-up and ray-cell hit\n\n";
  table.print(std::cout);
  return 0;
}

} // namespace meshpaint::cli
