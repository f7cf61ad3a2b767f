#include "StudioWindow.h"

#include "BackgroundTask.h"
#include "BrushPanel.h"
#include "FitDialog.h"
#include "HistoryPanel.h"
#include "LabelPanel.h"
#include "LevelPanel.h"
#include "DisplayPanel.h"
#include "PreferencesDialog.h"

#include "BrushSettings.h"    // for meshpaint::BrushSettings
#include "PaintingExport.h"   // for meshpaint::export_gltf, default_model_level
#include "PatchBorders.h"     // for meshpaint::patch_borders
#include "ScanTransfer.h"     // for meshpaint::read_scan, transfer_to_scan, write_transferred_scan
#include "SceneFiles.h"       // for meshpaint::export_scene
#include "SurfaceRendering.h" // for meshpaint::write_screenshot
#include "vtkPaintSurface.h"  // for vtkPaintSurface
#include "vtkPaintView.h"     // for vtkPaintView

#include "atlas/atlas_storage.h"        // for meshpaint::default_storage, parse_storage
#include "cl/runtime.h"                 // for meshpaint::Runtime
#include "core/cancellation.h"          // for meshpaint::stop_if_cancelled
#include "core/errors.h"                // for meshpaint::InputError
#include "mesh/base_mesh.h"             // for meshpaint::BaseMesh
#include "paint/paint_scene.h"          // for meshpaint::PaintScene
#include "paint/paint_surface.h"        // for meshpaint::PaintSurface
#include "project/imported_channels.h"   // for meshpaint::apply_imported_channels
#include "project/imported_labels.h"   // for meshpaint::apply_imported_labels
#include "project/labels.h"            // for meshpaint::load_labels
#include "project/project_surface.h"    // for meshpaint::capture_surface, reference_surface, stroke_history
#include "RasterIO.h"                   // for meshpaint::load_stroke_rasters

#include <QAbstractSpinBox>         // for QAbstractSpinBox
#include <QAction>                  // for QAction
#include <QApplication>             // for qApp
#include <QComboBox>                // for QComboBox
#include <QLineEdit>                // for QLineEdit
#include <QPlainTextEdit>           // for QPlainTextEdit
#include <QTextEdit>                // for QTextEdit
#include <QCheckBox>                // for QCheckBox
#include <QCoreApplication>         // for QCoreApplication
#include <QDockWidget>              // for QDockWidget
#include <QDragEnterEvent>          // for QDragEnterEvent
#include <QDropEvent>               // for QDropEvent
#include <QKeyEvent>                // for QKeyEvent
#include <QMimeData>                // for QMimeData
#include <QUrl>                     // for QUrl
#include <QFileDialog>              // for QFileDialog
#include <QFileInfo>                // for QFileInfo
#include <QGuiApplication>          // for QGuiApplication::primaryScreen
#include <QScreen>                  // for QScreen::availableGeometry
#include <QKeySequence>             // for QKeySequence
#include <QLabel>                   // for QLabel
#include <QMenu>                    // for QMenu
#include <QMenuBar>                 // for QMenuBar
#include <QMessageBox>              // for QMessageBox::question
#include <QScrollArea>              // for QScrollArea
#include <QSettings>                // for QSettings
#include <QStatusBar>               // for QStatusBar
#include <QVTKOpenGLNativeWidget.h> // for QVTKOpenGLNativeWidget

#include <vtkActor.h>                      // for vtkActor
#include <vtkCommand.h>                    // for vtkCommand
#include <vtkGenericOpenGLRenderWindow.h> // for vtkGenericOpenGLRenderWindow
#include <vtkNew.h>                        // for vtkNew
#include <vtkPoints.h>                     // for vtkPoints
#include <vtkPolyData.h>                   // for vtkPolyData
#include <vtkPolyDataMapper.h>             // for vtkPolyDataMapper
#include <vtkProperty.h>                   // for vtkProperty
#include <vtkRenderer.h>                   // for vtkRenderer

namespace meshpaint::studio {
namespace {

QDockWidget* dock(QMainWindow* window, const QString& title, QWidget* panel, Qt::DockWidgetArea area)
{
  auto* d = new QDockWidget(title, window);
  d->setObjectName(title);
  auto* scroll = new QScrollArea;
  scroll->setWidget(panel);
  scroll->setWidgetResizable(true);
  d->setWidget(scroll);
  window->addDockWidget(area, d);
  return d;
}

//! The mesh and project files a drop carries (local files only).
QStringList dropped_files(const QMimeData* data)
{
  QStringList files;
  if (data && data->hasUrls())
    for (const QUrl& url : data->urls())
      if (url.isLocalFile())
        files << url.toLocalFile();
  return files;
}

} // namespace

StudioWindow::StudioWindow(vtkPaintView* view, QWidget* parent)
  : QMainWindow(parent), view_(view), program_(QCoreApplication::applicationFilePath())
{
  setWindowTitle("meshpaint");
  widget_ = new QVTKOpenGLNativeWidget(this);
  widget_->setObjectName("view");
  vtkNew<vtkGenericOpenGLRenderWindow> window;
  widget_->setRenderWindow(window);
  setCentralWidget(widget_);
  widget_->setFocusPolicy(Qt::StrongFocus); // the window's keys go to the view, as in vtkPaintView's own window
  widget_->setFocus();
  view_->SetRenderWindow(window);
  if (!view_->Initialize()) {
    error_ = view_->GetLastError();
    return;
  }
  brush_ = new BrushPanel(view_);
  brush_->watch(widget_);
  labels_ = new LabelPanel(view_);
  labels_->watch(widget_);
  history_ = new HistoryPanel(view_);
  levels_ = new LevelPanel(view_, [this](int level) { change_level(level); });
  display_ = new DisplayPanel(view_, [this](bool on) { show_patch_borders(on); });
  QDockWidget* brush_dock = dock(this, "Brush", brush_, Qt::LeftDockWidgetArea);
  QDockWidget* display_dock = dock(this, "Display", display_, Qt::LeftDockWidgetArea);
  QDockWidget* level_dock = dock(this, "Level", levels_, Qt::LeftDockWidgetArea);
  QDockWidget* label_dock = dock(this, "Label classes", labels_, Qt::RightDockWidgetArea);
  QDockWidget* history_dock = dock(this, "History", history_, Qt::RightDockWidgetArea);
  status_ = new QLabel;
  status_->setObjectName("status");
  statusBar()->addWidget(status_, 1);
  build_menus();
  QMenu* panels = menuBar()->addMenu("&Panels");
  for (QDockWidget* d : {brush_dock, display_dock, level_dock, label_dock, history_dock})
    panels->addAction(d->toggleViewAction());
  observers_[0] = view_->AddObserver(vtkCommand::UpdateDataEvent, this, &StudioWindow::view_changed);
  observers_[3] = view_->AddObserver(vtkCommand::ExitEvent, this, &StudioWindow::quit_key);
  observers_[1] = window->AddObserver(vtkCommand::StartEvent, this, &StudioWindow::frame_started);
  observers_[2] = window->AddObserver(vtkCommand::EndEvent, this, &StudioWindow::frame_ended);
  // Files dropped anywhere on the window open; the view widget leaves drops to it.
  setAcceptDrops(true);
  widget_->setAcceptDrops(false);
  widget_->installEventFilter(this);
  qApp->installEventFilter(this); // keys typed into the panels (eventFilter())
  // The view's size (--size) with the panels around it, but no larger than
  // the screen leaves free: there the view gives way and the docks stay.
  const int* size = view_->GetSize();
  QSize wanted(size[0] + 640, size[1] + 90);
  if (const QScreen* screen = QGuiApplication::primaryScreen())
    wanted = wanted.boundedTo(screen->availableGeometry().size());
  resize(wanted);
  show_status();
}

StudioWindow::~StudioWindow()
{
  delete task_; // waits for the work, which holds the view's surfaces
  task_ = nullptr;
  view_->RemoveObserver(observers_[0]);
  view_->RemoveObserver(observers_[3]);
  if (vtkRenderWindow* w = widget_->renderWindow()) {
    w->RemoveObserver(observers_[1]);
    w->RemoveObserver(observers_[2]);
  }
}

void StudioWindow::build_menus()
{
  QMenu* file = menuBar()->addMenu("&File");
  file->addAction("&Open mesh or project...", [this] {
    const QString path = QFileDialog::getOpenFileName(this, "Open a mesh or a project", QString(),
                                                      "Meshes and projects (*.obj *.off *.ply *.stl *.vtp *.vtk *.meshpaint);;All files (*)");
    if (!path.isEmpty())
      open_path(path);
  }, QKeySequence(QKeySequence::Open));
  file->addAction("&Fit a scan...", [this] {
    const QString scan = QFileDialog::getOpenFileName(this, "Scan to fit", QString(),
                                                      "Meshes (*.obj *.off *.ply *.stl *.vtp *.vtk);;All files (*)");
    if (scan.isEmpty())
      return;
    const QString out = QFileDialog::getSaveFileName(this, "Project to write", QString(), "Projects (*.meshpaint)");
    if (!out.isEmpty())
      fit_scan(scan, out.endsWith(".meshpaint") ? out : out + ".meshpaint");
  });
  file->addAction("Load label &classes...", [this] {
    const QString path = QFileDialog::getOpenFileName(this, "Label classes", QString(),
                                                      "Labels files (*.json);;All files (*)");
    if (!path.isEmpty())
      load_label_classes(path);
  });
  recent_ = file->addMenu("Open &recent");
  fill_recent();
  file->addSeparator();
  surface_actions_.push_back(
    file->addAction("&Save session", [this] { view_->Save(); }, QKeySequence(QKeySequence::Save)));
  surface_actions_.push_back(file->addAction("Save project &as...", [this] {
    const QString path = QFileDialog::getSaveFileName(this, "Save the project", QString(), "Projects (*.meshpaint)");
    if (!path.isEmpty())
      save_project(path.endsWith(".meshpaint") ? path : path + ".meshpaint");
  }, QKeySequence(QKeySequence::SaveAs)));
  surface_actions_.push_back(
    file->addAction("&Export model", [this] { export_model(); }, QKeySequence(Qt::CTRL + Qt::Key_E)));
  surface_actions_.push_back(file->addAction("Export g&lTF...", [this] {
    const QString path = QFileDialog::getSaveFileName(this, "Export the model as glTF", QString(),
                                                      "glTF (*.glb *.gltf)");
    if (!path.isEmpty())
      export_gltf(path.endsWith(".glb") || path.endsWith(".gltf") ? path : path + ".glb");
  }));
  surface_actions_.push_back(file->addAction("Export the &labelled scan...", [this] {
    const QString scan = QFileDialog::getOpenFileName(this, "The scan to label", QString(),
                                                      "Scans (*.obj *.off *.ply *.stl *.vtp *.vtk);;All files (*)");
    if (scan.isEmpty())
      return;
    const QString out = QFileDialog::getSaveFileName(this, "The labelled scan to write", QString(),
                                                     "VTK polygons (*.vtp);;PLY (*.ply)");
    if (out.isEmpty())
      return;
    // As `transfer --geometry`: the scan's vertices follow the sculpting and smoothing.
    const bool geometry =
      QMessageBox::question(this, "The labelled scan",
                            "Move the scan's vertices as the surface was sculpted and smoothed?\n"
                            "(No: the scan keeps its shape and takes the labels and paint only.)",
                            QMessageBox::Yes | QMessageBox::No, QMessageBox::No) == QMessageBox::Yes;
    export_labelled_scan(scan, out.endsWith(".vtp") || out.endsWith(".ply") ? out : out + ".vtp", geometry);
  }));
  file->addAction("Screens&hot...", [this] {
    const QString path = QFileDialog::getSaveFileName(this, "Screenshot", QString(), "PNG pictures (*.png)");
    if (!path.isEmpty())
      screenshot(path.endsWith(".png") ? path : path + ".png");
  });
  file->addSeparator();
  file->addAction("&Preferences...", [this] { preferences()->exec(); });
  file->addSeparator();
  file->addAction("&Quit", [this] { close(); }, QKeySequence(QKeySequence::Quit));
  QMenu* edit = menuBar()->addMenu("&Edit");
  surface_actions_.push_back(edit->addAction("&Undo", [this] { view_->Undo(); }, QKeySequence(QKeySequence::Undo)));
  surface_actions_.push_back(
    edit->addAction("&Redo", [this] { view_->Redo(); }, QKeySequence(Qt::CTRL + Qt::Key_Y)));
  QMenu* show = menuBar()->addMenu("&View");
  show->addAction("&Reset camera", [this] { view_->HandleKey("r", false, false); });
  show->addAction("Key &help", [this] { view_->SetHelpVisible(!view_->GetHelpVisible()); });
  borders_action_ = show->addAction("&Patch borders", [this](bool on) { show_patch_borders(on); });
  borders_action_->setObjectName("patch_borders");
  borders_action_->setCheckable(true);
}

bool StudioWindow::open_path(const QString& path)
{
  if (busy()) {
    statusBar()->showMessage("busy: wait for the work running to finish before opening " + path, 10000);
    return false;
  }
  const std::string p = path.toStdString();
  int ok = 0;
  if (path.endsWith(".meshpaint", Qt::CaseInsensitive)) {
    vtkNew<vtkPaintSurface> filter;
    filter->SetDevice(view_->GetDevice());
    ok = filter->LoadProject(p.c_str()) && view_->SetPaintSurface(filter);
    if (ok)
      project_ = filter.GetPointer();
    else if (*filter->GetLastError())
      statusBar()->showMessage(filter->GetLastError(), 10000);
  } else {
    ok = view_->LoadMesh(p.c_str());
  }
  if (!ok) {
    if (*view_->GetLastError())
      statusBar()->showMessage(view_->GetLastError(), 10000);
    return false;
  }
  const QFileInfo info(path);
  view_->SetSaveDirectory((info.absolutePath() + "/" + info.completeBaseName() + "-session").toStdString().c_str());
  view_->HandleKey("r", false, false); // the camera onto the new surface
  add_recent(info.absoluteFilePath());
  setWindowTitle("meshpaint - " + info.fileName());
  borders_of_.clear(); // other surfaces: new lines
  view_changed();
  return true;
}

bool StudioWindow::load_label_classes(const QString& path)
{
  try {
    view_->SetLabelClasses(load_labels(path.toStdString()));
  } catch (const std::exception& e) {
    statusBar()->showMessage(e.what(), 10000);
    return false;
  }
  statusBar()->showMessage(QString("label classes from %1: %2").arg(path).arg(view_->GetNumberOfLabelClasses()), 10000);
  view_changed();
  return true;
}

FitDialog* StudioWindow::fit_scan(const QString& scan, const QString& out)
{
  auto* dialog = new FitDialog(program_, scan, out, [this, out](bool ok) {
    if (ok)
      open_path(out);
  }, this);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  dialog->show();
  dialog->start();
  return dialog;
}

bool StudioWindow::save_project(const QString& path)
{
  const bool ok = view_->SaveProject(path.toStdString().c_str());
  if (ok)
    add_recent(QFileInfo(path).absoluteFilePath());
  return ok;
}

bool StudioWindow::screenshot(const QString& path)
{
  try {
    write_screenshot(view_->GetRenderWindow(), path.toStdString());
  } catch (const std::exception& e) {
    statusBar()->showMessage(e.what(), 10000);
    return false;
  }
  statusBar()->showMessage("wrote " + path, 5000);
  return true;
}

void StudioWindow::add_recent(const QString& path)
{
  QSettings settings;
  QStringList files = settings.value("recent").toStringList();
  files.removeAll(path);
  files.prepend(path);
  while (files.size() > 8)
    files.removeLast();
  settings.setValue("recent", files);
  fill_recent();
}

void StudioWindow::fill_recent()
{
  recent_->clear();
  for (const QString& path : QSettings().value("recent").toStringList())
    recent_->addAction(path, [this, path] { open_path(path); });
  recent_->setEnabled(!recent_->isEmpty());
}

void StudioWindow::view_changed()
{
  if (!brush_)
    return;
  brush_->sync();
  if (!busy()) // its areas are measured on the surface, which the work running may be reading
    labels_->sync();
  history_->sync();
  levels_->sync();
  display_->sync();
  update_patch_borders();
  show_status();
}

void StudioWindow::quit_key()
{
  // Qt's interactor does not end the event loop itself; the window closes later, out of VTK's event.
  QMetaObject::invokeMethod(this, &QWidget::close, Qt::QueuedConnection);
}

void StudioWindow::frame_started() { frame_start_ = std::chrono::steady_clock::now(); }

void StudioWindow::frame_ended()
{
  frame_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - frame_start_).count();
  show_status();
}

void StudioWindow::show_status()
{
  if (!status_)
    return;
  PaintScene& scene = view_->GetScene();
  const QString device =
    scene.empty() ? QString("-") : QString::fromStdString(scene.surface(0).atlas().runtime().info().name);
  status_->setText(QString("device %1   |   brush step %2 ms   |   frame %3 ms (%4 fps)   |   %5 strokes   |   %6")
                     .arg(device)
                     .arg(view_->GetLastStepTime(), 0, 'f', 1)
                     .arg(frame_ms_, 0, 'f', 1)
                     .arg(frame_ms_ > 0 ? 1000.0 / frame_ms_ : 0.0, 0, 'f', 0)
                     .arg(scene.history().size())
                     .arg(QString::fromStdString(view_->GetMessage())));
}

BackgroundTask* StudioWindow::run_locked(const QString& what,
                                         const std::function<QString(const std::atomic<bool>&)>& work,
                                         const std::function<void(bool)>& done, bool cancellable)
{
  if (busy()) {
    statusBar()->showMessage("busy: wait for the work running to finish", 10000);
    return nullptr;
  }
  if (view_->GetNumberOfObjects() == 0 || view_->IsPainting()) {
    statusBar()->showMessage(view_->IsPainting() ? "finish the stroke first" : "no surface", 10000);
    return nullptr;
  }
  view_->SetLocked(true);
  for (QAction* a : surface_actions_)
    a->setEnabled(false);
  levels_->set_busy(true);
  statusBar()->showMessage(what);
  task_ = new BackgroundTask(this, what, work, [this, done](bool ok, const QString& line) {
    task_ = nullptr;
    view_->SetLocked(false);
    for (QAction* a : surface_actions_)
      a->setEnabled(true);
    levels_->set_busy(false);
    if (done)
      done(ok);
    statusBar()->showMessage(line, 10000);
    view_changed();
  }, cancellable);
  task_->start();
  return task_;
}

BackgroundTask* StudioWindow::export_model()
{
  const std::string dir = view_->GetSaveDirectory();
  const int model_level = default_model_level(view_->GetLevel());
  return run_locked(
    "exporting the model into " + QString::fromStdString(dir),
    [this, dir, model_level](const std::atomic<bool>& cancelled) {
      return QString::fromStdString(export_scene(view_->GetScene(), model_level, dir, &cancelled));
    },
    nullptr, true);
}

BackgroundTask* StudioWindow::export_gltf(const QString& path)
{
  const std::string out = path.toStdString();
  const int model_level = default_model_level(view_->GetLevel());
  return run_locked(
    "exporting " + path,
    [this, out, path, model_level](const std::atomic<bool>& cancelled) {
      PaintScene& scene = view_->GetScene();
      if (scene.size() != 1)
        throw InputError("glTF keeps one surface: this scene has " + std::to_string(scene.size()));
      meshpaint::export_gltf(scene.surface(0), model_level, out, &cancelled);
      return "exported " + path;
    },
    nullptr, true);
}

BackgroundTask* StudioWindow::change_level(int level)
{
  // What the work needs, taken here: the view's state is the interface thread's.
  PaintScene& scene = view_->GetScene();
  std::vector<BaseMesh> meshes;
  std::vector<std::string> names;
  for (std::size_t k = 0; k < scene.size(); ++k) {
    meshes.push_back(scene.surface(k).atlas().base_mesh());
    names.push_back(scene.name(k));
  }
  std::vector<Stroke> strokes = scene.history();
  // A project's surface is where its own history led from its start (its
  // reference, else the mesh): that history is replayed first, and the
  // project continues at the new level with it in the surface's strokes.
  std::shared_ptr<Project> continued;
  if (const Project* project = view_->GetProject()) {
    continued = std::make_shared<Project>(*project);
    try {
      StrokeScript earlier = stroke_history(project->history);
      load_stroke_rasters(earlier);
      strokes.insert(strokes.begin(), earlier.strokes.begin(), earlier.strokes.end());
    } catch (const std::exception& e) {
      statusBar()->showMessage(QString("cannot replay the project's strokes: ") + e.what(), 10000);
      return nullptr;
    }
    continued->history.clear();
    continued->origin = view_->GetProjectOrigin();
    continued->labels = view_->GetLabelClasses();
  }
  const std::string device = view_->GetDevice(), storage = view_->GetStorage();
  auto rebuilt = std::make_shared<PaintScene>();
  return run_locked(
    QString("subdividing at level %1 and replaying %2 strokes").arg(level).arg(strokes.size()),
    [=](const std::atomic<bool>& cancelled) {
      auto runtime = Runtime::open(device);
      const AtlasStorage chosen = storage.empty() ? default_storage(runtime->info()) : parse_storage(storage);
      for (std::size_t k = 0; k < meshes.size(); ++k) {
        stop_if_cancelled(&cancelled);
        auto surface = std::make_shared<PaintSurface>(runtime, meshes[k], level, chosen);
        apply_imported_channels(*surface);
        apply_imported_labels(*surface);
        if (continued && !continued->reference.empty()) { // a fitted project starts from its fit
          continued->reference = reference_at_level(runtime, *continued, level, chosen);
          surface->atlas().write_positions(level, continued->reference);
          surface->geometry_changed();
        }
        rebuilt->add(std::move(surface), names[k]);
      }
      for (std::size_t k = 0; k < strokes.size(); ++k) {
        stop_if_cancelled(&cancelled);
        if (strokes[k].edit_level() > level)
          throw InputError("stroke " + std::to_string(k + 1) + " edits level " +
                           std::to_string(strokes[k].edit_level()) + ", finer than level " + std::to_string(level));
        rebuilt->apply(strokes[k]);
      }
      return QString("level %1: %2 strokes replayed").arg(level).arg(strokes.size());
    },
    [this, rebuilt, continued, level](bool ok) {
      if (!ok)
        return; // cancelled or failed: the scene stays as it was
      const BrushSettings brush = *view_->GetBrush();
      view_->SetSurface(rebuilt->shared(0), rebuilt->name(0));
      for (std::size_t k = 1; k < rebuilt->size(); ++k)
        view_->AddSurface(rebuilt->shared(k), rebuilt->name(k));
      if (continued) { // saves continue the project, at the new level
        continued->level = level;
        view_->SetProject(*continued);
        project_ = nullptr; // the filter's surface is the old level's
      }
      *view_->GetBrush() = brush; // the same brush, on the new level
      view_->GetBrush()->set_level(view_->GetLevel());
      borders_of_.clear();
      view_->UpdateText();
      view_->Render();
    },
    true);
}

BackgroundTask* StudioWindow::export_labelled_scan(const QString& scan, const QString& out, bool geometry)
{
  if (view_->GetNumberOfObjects() != 1) {
    statusBar()->showMessage("the labelled scan comes from one surface: this scene has several", 10000);
    return nullptr;
  }
  Project base = view_->GetProject() ? *view_->GetProject() : Project();
  const std::vector<LabelClass> labels = view_->GetLabelClasses();
  const std::string scan_path = scan.toStdString(), out_path = out.toStdString();
  return run_locked(
    "writing the labelled scan " + out,
    [=](const std::atomic<bool>& cancelled) {
      vtkSmartPointer<vtkPolyData> points = read_scan(scan_path);
      stop_if_cancelled(&cancelled);
      PaintSurface& surface = view_->GetScene().surface(0);
      Project project = base;
      capture_surface(surface, project); // the surface's mesh and level: the reference is made from them
      const std::shared_ptr<Runtime>& runtime = surface.atlas().shared_runtime();
      const WeldedSurface reference = reference_surface(runtime, project, surface.atlas().storage());
      stop_if_cancelled(&cancelled);
      const TransferReport r = transfer_to_scan(surface.painted_surface(), reference, points, geometry);
      stop_if_cancelled(&cancelled); // the last boundary: the write renames its file into place
      write_transferred_scan(points, out_path, labels);
      return QString("wrote %1: %2 scan vertices, at most %3 from the surface")
        .arg(out)
        .arg(points->GetNumberOfPoints())
        .arg(r.max_distance);
    },
    nullptr, true);
}

void StudioWindow::show_patch_borders(bool on)
{
  if (borders_action_ && borders_action_->isChecked() != on)
    borders_action_->setChecked(on);
  if (display_ && display_->borders()->isChecked() != on)
    display_->borders()->setChecked(on);
  if (!on) {
    for (const auto& actor : borders_)
      view_->GetRenderer()->RemoveActor(actor);
    borders_.clear();
    borders_of_.clear();
    borders_time_.clear();
    view_->Render();
    return;
  }
  update_patch_borders();
}

void StudioWindow::update_patch_borders()
{
  if (!borders_action_ || !borders_action_->isChecked() || busy())
    return;
  const int objects = view_->GetNumberOfObjects();
  bool changed = int(borders_.size()) != objects;
  for (int k = 0; k < objects && !changed; ++k) {
    vtkPolyData* poly = view_->GetPaintedPolyData(k);
    changed = poly != borders_of_[std::size_t(k)] || poly->GetPoints()->GetMTime() != borders_time_[std::size_t(k)];
  }
  if (!changed)
    return;
  for (const auto& actor : borders_)
    view_->GetRenderer()->RemoveActor(actor);
  borders_.clear();
  borders_of_.clear();
  borders_time_.clear();
  const int n = 1 << (view_->GetLevel() - 1);
  for (int k = 0; k < objects; ++k) {
    vtkPolyData* poly = view_->GetPaintedPolyData(k);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(patch_borders(poly, n));
    mapper->ScalarVisibilityOff();
    // The lines lie on the surface: drawn in front of it.
    mapper->SetResolveCoincidentTopologyToPolygonOffset();
    mapper->SetRelativeCoincidentTopologyLineOffsetParameters(0, -4);
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->PickableOff();
    actor->GetProperty()->SetColor(0.05, 0.15, 0.45);
    actor->GetProperty()->SetLineWidth(1.0);
    actor->GetProperty()->LightingOff();
    view_->GetRenderer()->AddActor(actor);
    borders_.push_back(actor);
    borders_of_.push_back(poly);
    borders_time_.push_back(poly->GetPoints()->GetMTime());
  }
  view_->Render();
}

vtkPolyData* StudioWindow::patch_border_lines(int object)
{
  if (object < 0 || std::size_t(object) >= borders_.size())
    return nullptr;
  return vtkPolyData::SafeDownCast(borders_[std::size_t(object)]->GetMapper()->GetInput());
}

PreferencesDialog* StudioWindow::preferences()
{
  if (!preferences_)
    preferences_ = new PreferencesDialog(view_, this);
  return preferences_;
}

void StudioWindow::dragEnterEvent(QDragEnterEvent* event)
{
  if (!dropped_files(event->mimeData()).isEmpty())
    event->acceptProposedAction();
}

void StudioWindow::dropEvent(QDropEvent* event)
{
  const QStringList files = dropped_files(event->mimeData());
  if (files.isEmpty())
    return;
  event->acceptProposedAction();
  if (files.size() > 1)
    statusBar()->showMessage("one file at a time: opening " + files.front(), 10000);
  open_path(files.front());
}

namespace {

//! Whether `w` takes typed characters itself: text and number fields (a
//! table cell being edited has such an editor, which has the focus), an
//! editable combo box.
bool takes_typing(const QWidget* w)
{
  const auto* combo = qobject_cast<const QComboBox*>(w);
  return qobject_cast<const QLineEdit*>(w) || qobject_cast<const QAbstractSpinBox*>(w) ||
         qobject_cast<const QPlainTextEdit*>(w) || qobject_cast<const QTextEdit*>(w) || (combo && combo->isEditable());
}

} // namespace

bool StudioWindow::eventFilter(QObject* watched, QEvent* event)
{
  // The view's one-character keys (t, v, q, [, 1 ...) work after a click on
  // a panel too: a key typed into a panel widget of this window that does
  // not take typing goes to the view, as if it had the focus.
  if (event->type() == QEvent::KeyPress && watched != widget_ && widget_ && watched->isWidgetType()) {
    auto* w = static_cast<QWidget*>(watched);
    const auto* key = static_cast<QKeyEvent*>(event);
    const QString text = key->text();
    const bool character = text.size() == 1 && text[0].isPrint() && !text[0].isSpace() &&
                           !(key->modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier));
    // Not the window or a dock around the view: a key the view left goes up to them.
    if (character && w->window() == this && !w->isAncestorOf(widget_) && !takes_typing(w)) {
      QKeyEvent copy(key->type(), key->key(), key->modifiers(), key->text(), key->isAutoRepeat(), ushort(key->count()));
      QCoreApplication::sendEvent(widget_, &copy);
      return true;
    }
  }

  // Ctrl+E in the view exports in the background, as the menu does, not in the view's own key handler.
  if (watched == widget_ && event->type() == QEvent::KeyPress) {
    const auto* key = static_cast<QKeyEvent*>(event);
    if (key->key() == Qt::Key_E && (key->modifiers() & Qt::ControlModifier)) {
      export_model();
      return true;
    }
  }
  return QMainWindow::eventFilter(watched, event);
}

} // namespace meshpaint::studio
