// The studio's main window: the painting view in VTK's Qt widget, the
// panels around it (brush, label classes, history), menus for files, and a
// status bar with the device, the brush step time and the frame rate.
#pragma once

#include <QMainWindow> // for QMainWindow
#include <QString>     // for QString

#include <vtkSmartPointer.h> // for vtkSmartPointer

#include <chrono> // for std::chrono::steady_clock

class QLabel;
class QMenu;
class QVTKOpenGLNativeWidget;
class vtkPaintSurface;
class vtkPaintView;

namespace meshpaint::studio {

class BrushPanel;
class FitDialog;
class HistoryPanel;
class LabelPanel;

class StudioWindow : public QMainWindow
{
public:
  //! Shows `view` (a surface loaded, not initialized) in the window.
  explicit StudioWindow(vtkPaintView* view, QWidget* parent = nullptr);
  ~StudioWindow() override;
  //! Whether the view could be set up in the window, and if not why.
  bool ready() const { return error_.isEmpty(); }
  QString error() const { return error_; }

  QVTKOpenGLNativeWidget* render_widget() { return widget_; }
  BrushPanel* brush_panel() { return brush_; }
  LabelPanel* label_panel() { return labels_; }
  HistoryPanel* history_panel() { return history_; }
  vtkPaintView* view() { return view_; }

  //! Opens a mesh file or a project (`*.meshpaint`) in place of what is
  //! painted; false (and a message in the status bar) when it cannot.
  bool open_path(const QString& path);
  //! Saves the surface as a project at `path`.
  bool save_project(const QString& path);
  //! Writes what the view shows as a PNG.
  bool screenshot(const QString& path);
  //! Fits `scan` into the project `out` in a FitDialog (the fit runs as a
  //! child process); the project opens when the fit succeeds.
  FitDialog* fit_scan(const QString& scan, const QString& out);
  //! The `meshpaint` executable fits run with (default: this program).
  void set_program(const QString& program) { program_ = program; }

private:
  void build_menus();
  void add_recent(const QString& path);
  void fill_recent();
  //! The view changed (a stroke, undo, a key): panels and status follow.
  void view_changed();
  //! q or Escape in the view: the window closes.
  void quit_key();
  void frame_started();
  void frame_ended();
  void show_status();

  vtkPaintView* view_;
  QString error_;
  QString program_;
  QVTKOpenGLNativeWidget* widget_;
  BrushPanel* brush_ = nullptr;
  LabelPanel* labels_ = nullptr;
  HistoryPanel* history_ = nullptr;
  QMenu* recent_ = nullptr;
  QLabel* status_ = nullptr;
  vtkSmartPointer<vtkPaintSurface> project_; // the filter a project was opened through
  std::chrono::steady_clock::time_point frame_start_;
  double frame_ms_ = 0;
  unsigned long observers_[4] = {0, 0, 0, 0};
};

} // namespace meshpaint::studio
