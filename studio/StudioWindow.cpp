#include "StudioWindow.h"

#include "BrushPanel.h"
#include "FitDialog.h"
#include "HistoryPanel.h"
#include "LabelPanel.h"

#include "SurfaceRendering.h" // for meshpaint::write_screenshot
#include "vtkPaintSurface.h"  // for vtkPaintSurface
#include "vtkPaintView.h"     // for vtkPaintView

#include "cl/runtime.h"          // for meshpaint::Runtime
#include "paint/paint_scene.h"   // for meshpaint::PaintScene
#include "paint/paint_surface.h" // for meshpaint::PaintSurface

#include <QAction>                  // for QAction
#include <QCoreApplication>         // for QCoreApplication
#include <QDockWidget>              // for QDockWidget
#include <QFileDialog>              // for QFileDialog
#include <QFileInfo>                // for QFileInfo
#include <QKeySequence>             // for QKeySequence
#include <QLabel>                   // for QLabel
#include <QMenu>                    // for QMenu
#include <QMenuBar>                 // for QMenuBar
#include <QScrollArea>              // for QScrollArea
#include <QSettings>                // for QSettings
#include <QStatusBar>               // for QStatusBar
#include <QVTKOpenGLNativeWidget.h> // for QVTKOpenGLNativeWidget

#include <vtkCommand.h>                    // for vtkCommand
#include <vtkGenericOpenGLRenderWindow.h> // for vtkGenericOpenGLRenderWindow
#include <vtkNew.h>                        // for vtkNew

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
  labels_ = new LabelPanel(view_);
  labels_->watch(widget_);
  history_ = new HistoryPanel(view_);
  QDockWidget* brush_dock = dock(this, "Brush", brush_, Qt::LeftDockWidgetArea);
  QDockWidget* label_dock = dock(this, "Label classes", labels_, Qt::RightDockWidgetArea);
  QDockWidget* history_dock = dock(this, "History", history_, Qt::RightDockWidgetArea);
  status_ = new QLabel;
  status_->setObjectName("status");
  statusBar()->addWidget(status_, 1);
  build_menus();
  QMenu* panels = menuBar()->addMenu("&Panels");
  for (QDockWidget* d : {brush_dock, label_dock, history_dock})
    panels->addAction(d->toggleViewAction());
  observers_[0] = view_->AddObserver(vtkCommand::UpdateDataEvent, this, &StudioWindow::view_changed);
  observers_[3] = view_->AddObserver(vtkCommand::ExitEvent, this, &StudioWindow::quit_key);
  observers_[1] = window->AddObserver(vtkCommand::StartEvent, this, &StudioWindow::frame_started);
  observers_[2] = window->AddObserver(vtkCommand::EndEvent, this, &StudioWindow::frame_ended);
  const int* size = view_->GetSize(); // the view's, with the panels around it
  resize(size[0] + 640, size[1] + 90);
  show_status();
}

StudioWindow::~StudioWindow()
{
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
  recent_ = file->addMenu("Open &recent");
  fill_recent();
  file->addSeparator();
  file->addAction("&Save session", [this] { view_->Save(); }, QKeySequence(QKeySequence::Save));
  file->addAction("Save project &as...", [this] {
    const QString path = QFileDialog::getSaveFileName(this, "Save the project", QString(), "Projects (*.meshpaint)");
    if (!path.isEmpty())
      save_project(path.endsWith(".meshpaint") ? path : path + ".meshpaint");
  }, QKeySequence(QKeySequence::SaveAs));
  file->addAction("&Export model", [this] { view_->Export(); }, QKeySequence(Qt::CTRL + Qt::Key_E));
  file->addAction("Screens&hot...", [this] {
    const QString path = QFileDialog::getSaveFileName(this, "Screenshot", QString(), "PNG pictures (*.png)");
    if (!path.isEmpty())
      screenshot(path.endsWith(".png") ? path : path + ".png");
  });
  file->addSeparator();
  file->addAction("&Quit", [this] { close(); }, QKeySequence(QKeySequence::Quit));
  QMenu* edit = menuBar()->addMenu("&Edit");
  edit->addAction("&Undo", [this] { view_->Undo(); }, QKeySequence(QKeySequence::Undo));
  edit->addAction("&Redo", [this] { view_->Redo(); }, QKeySequence(Qt::CTRL + Qt::Key_Y));
  QMenu* show = menuBar()->addMenu("&View");
  show->addAction("&Reset camera", [this] { view_->HandleKey("r", false, false); });
  show->addAction("Key &help", [this] { view_->SetHelpVisible(!view_->GetHelpVisible()); });
}

bool StudioWindow::open_path(const QString& path)
{
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
  labels_->sync();
  history_->sync();
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

} // namespace meshpaint::studio
