// The studio's main window: the painting view in VTK's Qt widget, the
// panels around it (brush, label classes, history), menus for files, and a
// status bar with the device, the brush step time and the frame rate.
#pragma once

#include <QMainWindow> // for QMainWindow
#include <QString>     // for QString

#include <vtkSmartPointer.h> // for vtkSmartPointer

#include <atomic>     // for std::atomic
#include <chrono>     // for std::chrono::steady_clock
#include <functional> // for std::function
#include <vector> // for std::vector

class QAction;
class QDragEnterEvent;
class QDropEvent;
class QLabel;
class QMenu;
class QVTKOpenGLNativeWidget;
class vtkActor;
class vtkPaintSurface;
class vtkPaintView;
class vtkPolyData;

namespace meshpaint::studio {

class BackgroundTask;
class BrushPanel;
class FitDialog;
class HistoryPanel;
class LabelPanel;
class LevelPanel;
class DisplayPanel;
class PreferencesDialog;

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
  LevelPanel* level_panel() { return levels_; }
  DisplayPanel* display_panel() { return display_; }
  vtkPaintView* view() { return view_; }

  //! Opens a mesh file or a project (`*.meshpaint`) in place of what is
  //! painted; false (and a message in the status bar) when it cannot.
  bool open_path(const QString& path);
  //! Takes the classes of labels file `path` (as `--labels`) in place of the
  //! view's; false (and the file's error in the status bar) when it cannot.
  bool load_label_classes(const QString& path);
  //! Saves the surface as a project at `path`.
  bool save_project(const QString& path);
  //! Writes what the view shows as a PNG.
  bool screenshot(const QString& path);
  //! Fits `scan` into the project `out` in a FitDialog (the fit runs as a
  //! child process); the project opens when the fit succeeds.
  FitDialog* fit_scan(const QString& scan, const QString& out);
  //! The `meshpaint` executable fits run with (default: this program).
  void set_program(const QString& program) { program_ = program; }

  //@{
  //! Long work on the surfaces, each on a worker thread (BackgroundTask)
  //! while the view is locked (vtkPaintView::SetLocked: no strokes, undo or
  //! saves meanwhile; the camera still turns). Each returns the task, or
  //! null (and a message in the status bar) while other work runs.
  //! The textured model of every object into the save folder (Ctrl+E).
  BackgroundTask* export_model();
  //! The first object's model as one glTF file (.glb or .gltf).
  BackgroundTask* export_gltf(const QString& path);
  //! The scene subdivided again at painting level `level` from its meshes,
  //! the strokes replayed on it (Cancel stops it; the scene stays as it was).
  BackgroundTask* change_level(int level);
  //! The labelled scan (`meshpaint transfer`): the channels and labels
  //! carried onto the vertices of `scan`, written to `out` (.vtp or .ply).
  BackgroundTask* export_labelled_scan(const QString& scan, const QString& out, bool geometry = false);
  //! Whether such work runs now.
  bool busy() const { return task_ != nullptr; }
  //! The work running, null when none.
  BackgroundTask* task() { return task_; }
  //@}

  //! The atlas's patch borders drawn over the surfaces (View menu, level panel).
  void show_patch_borders(bool on);
  //! The lines drawn for object `object`'s patch borders; null when hidden.
  vtkPolyData* patch_border_lines(int object = 0);
  //! Opens the preferences (device, storage).
  PreferencesDialog* preferences();

protected:
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;
  bool eventFilter(QObject* watched, QEvent* event) override;

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
  //! Starts `work` in the background unless other work runs (see export_model()).
  BackgroundTask* run_locked(const QString& what, const std::function<QString(const std::atomic<bool>&)>& work,
                             const std::function<void(bool)>& done, bool cancellable);
  //! The patch border lines follow the surfaces shown.
  void update_patch_borders();

  vtkPaintView* view_;
  QString error_;
  QString program_;
  QVTKOpenGLNativeWidget* widget_;
  BrushPanel* brush_ = nullptr;
  LabelPanel* labels_ = nullptr;
  HistoryPanel* history_ = nullptr;
  LevelPanel* levels_ = nullptr;
  DisplayPanel* display_ = nullptr;
  BackgroundTask* task_ = nullptr;
  PreferencesDialog* preferences_ = nullptr;
  std::vector<QAction*> surface_actions_; // what changes the surfaces: off while a task runs
  QAction* borders_action_ = nullptr;
  std::vector<vtkSmartPointer<vtkActor>> borders_; // one per object, while shown
  std::vector<vtkPolyData*> borders_of_;           // the painted surfaces the lines were made from
  std::vector<unsigned long> borders_time_;        // and their points' modification times then
  QMenu* recent_ = nullptr;
  QLabel* status_ = nullptr;
  vtkSmartPointer<vtkPaintSurface> project_; // the filter a project was opened through
  std::chrono::steady_clock::time_point frame_start_;
  double frame_ms_ = 0;
  unsigned long observers_[4] = {0, 0, 0, 0};
};

} // namespace meshpaint::studio
