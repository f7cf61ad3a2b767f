// The studio driven by real Qt mouse and key events under xvfb-run: drags
// paint on meshes wound either way, a label class chosen in its list paints
// its id in its colour, the label panel locks, fills, picks and merges, the
// history list undoes, and a saved session replays to the same bits with
// `meshpaint paint`; exports, level changes and the labelled scan run off
// the interface thread, preferences persist, and a file dropped on the
// window opens.

#include "BackgroundTask.h"
#include "BrushPanel.h"
#include "ChannelDisplay.h"
#include "BrushSettings.h"
#include "FitDialog.h"
#include "HistoryPanel.h"
#include "LabelPanel.h"
#include "LevelPanel.h"
#include "DisplayPanel.h"
#include "PolyDataFiles.h"
#include "PreferencesDialog.h"
#include "Studio.h"
#include "StudioWindow.h"
#include "vtkPaintView.h"

#include "atlas/atlas.h"
#include "mesh/base_mesh.h"
#include "paint/paint_memory.h"
#include "paint/paint_scene.h"
#include "paint/paint_surface.h"
#include "project/project.h"

#include <QAbstractSpinBox>         // for QAbstractSpinBox
#include <QApplication>             // for QApplication
#include <QCheckBox>                // for QCheckBox
#include <QComboBox>                // for QComboBox
#include <QDir>                     // for QDir
#include <QDockWidget>              // for QDockWidget
#include <QGuiApplication>          // for QGuiApplication::primaryScreen
#include <QScreen>                  // for QScreen
#include <QDragEnterEvent>          // for QDragEnterEvent
#include <QDropEvent>               // for QDropEvent
#include <QFile>                    // for QFile
#include <QFileInfo>                // for QFileInfo
#include <QMap>                     // for QMap
#include <QMimeData>                // for QMimeData
#include <QSemaphore>               // for QSemaphore
#include <QSettings>                // for QSettings
#include <QStatusBar>               // for QStatusBar
#include <QThreadPool>              // for QThreadPool
#include <QSpinBox>                 // for QSpinBox
#include <QTimer>                   // for QTimer
#include <QUrl>                     // for QUrl
#include <QImage>                   // for QImage
#include <QListWidget>              // for QListWidget
#include <QMouseEvent>              // for QMouseEvent
#include <QProcess>                 // for QProcess
#include <QProgressDialog>          // for QProgressDialog
#include <QPushButton>              // for QPushButton
#include <QTableWidget>             // for QTableWidget
#include <QTemporaryDir>            // for QTemporaryDir
#include <QTest>                    // for QTest
#include <QVTKOpenGLNativeWidget.h> // for QVTKOpenGLNativeWidget

#include <vtkCellArray.h>          // for vtkCellArray
#include <vtkDataArray.h>          // for vtkDataArray
#include <vtkFieldData.h>          // for vtkFieldData
#include <vtkNew.h>                // for vtkNew
#include <vtkPointData.h>          // for vtkPointData
#include <vtkRenderWindow.h>       // for vtkRenderWindow
#include <vtkPolyData.h>           // for vtkPolyData
#include <vtkSmartPointer.h>       // for vtkSmartPointer
#include <vtkXMLPolyDataReader.h>  // for vtkXMLPolyDataReader

#include <algorithm> // for std::count
#include <array>   // for std::array
#include <cmath>   // for std::abs
#include <cstring> // for std::memcmp
#include <memory>  // for std::unique_ptr

using meshpaint::studio::StudioWindow;

namespace {

const QString kCube = QString(MESHPAINT_SOURCE_DIR) + "/tests/support/cube.obj";

//! The test cube without its back face (z = 0: open, so the import leaves
//! its winding as it is) and its faces wound the other way, normals
//! inwards, written into `dir`.
QString inward_cube(const QTemporaryDir& dir)
{
  QFile in(kCube);
  in.open(QIODevice::ReadOnly);
  QString out;
  for (const QString& line : QString(in.readAll()).split('\n')) {
    QStringList parts = line.split(' ', Qt::SkipEmptyParts);
    if (line.trimmed() == "f 1 4 3 2")
      continue;
    if (!parts.isEmpty() && parts[0] == "f")
      std::reverse(parts.begin() + 1, parts.end());
    out += parts.join(' ') + "\n";
  }
  const QString path = dir.filePath("inward.obj");
  QFile f(path);
  f.open(QIODevice::WriteOnly);
  f.write(out.toUtf8());
  return path;
}

//! A studio on `mesh` at level 4, shown and exposed, its brush twice the
//! texel spacing (a dab with no texel within its radius is off the surface).
std::unique_ptr<StudioWindow> show_studio(vtkPaintView* view);

std::unique_ptr<StudioWindow> open_studio(vtkPaintView* view, const QString& mesh, const QString& save_dir)
{
  view->SetLevel(4);
  view->SetSaveDirectory(save_dir.toStdString().c_str());
  if (!view->LoadMesh(mesh.toStdString().c_str()))
    qFatal("cannot load %s: %s", qPrintable(mesh), view->GetLastError());
  return show_studio(view);
}

//! The studio on the surfaces `view` has, shown and exposed, its brush
//! twice the texel spacing.
std::unique_ptr<StudioWindow> show_studio(vtkPaintView* view)
{
  auto window = std::make_unique<StudioWindow>(view);
  if (!window->ready())
    qFatal("no studio: %s", qPrintable(window->error()));
  window->resize(1200, 800);
  window->show();
  QApplication::setActiveWindow(window.get()); // no window manager: shortcuts need an active window
  if (!QTest::qWaitForWindowExposed(window.get()))
    qFatal("the window was not exposed");
  QTest::qWait(50);
  for (int k = 0; k < 3; ++k)
    QTest::keyClick(window->render_widget(), Qt::Key_BracketRight);
  return window;
}

void mouse(QWidget* w, QEvent::Type type, const QPoint& at, Qt::MouseButton button, Qt::MouseButtons held)
{
  QMouseEvent e(type, at, w->mapToGlobal(at), button, held, Qt::NoModifier);
  QApplication::sendEvent(w, &e);
}

//! A left-drag across the widget, from `from` to `to` (fractions of its size).
void drag(QWidget* w, QPointF from, QPointF to, int steps = 10)
{
  QTest::qWait(20); // the item buffer is captured at rest
  const auto at = [&](double t) {
    return QPoint(int(w->width() * (from.x() + t * (to.x() - from.x()))),
                  int(w->height() * (from.y() + t * (to.y() - from.y()))));
  };
  mouse(w, QEvent::MouseMove, at(0), Qt::NoButton, Qt::NoButton);
  mouse(w, QEvent::MouseButtonPress, at(0), Qt::LeftButton, Qt::LeftButton);
  for (int k = 1; k <= steps; ++k) {
    mouse(w, QEvent::MouseMove, at(double(k) / steps), Qt::NoButton, Qt::LeftButton);
    QApplication::processEvents();
  }
  mouse(w, QEvent::MouseButtonRelease, at(1), Qt::LeftButton, Qt::NoButton);
  QApplication::processEvents();
}

std::size_t red_texels(vtkPaintView* view)
{
  std::size_t n = 0;
  for (const meshpaint::Float4& d : view->GetScene().surface(0).read_channels().diffuse)
    n += d[0] > 0.8f && d[1] < 0.2f;
  return n;
}

//! Pixels of the view close to `colour` (within 40 per channel).
int pixels_like(StudioWindow& w, const QColor& colour)
{
  const QImage image = w.render_widget()->grabFramebuffer();
  int n = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const QColor c = image.pixelColor(x, y);
      n += std::abs(c.red() - colour.red()) < 40 && std::abs(c.green() - colour.green()) < 40 &&
           std::abs(c.blue() - colour.blue()) < 40;
    }
  return n;
}

vtkSmartPointer<vtkPolyData> read_vtp(const QString& path)
{
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(path.toStdString().c_str());
  reader->Update();
  return reader->GetOutput();
}

QByteArray file_bytes(const QString& path)
{
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

//! Every file of `folder` (hidden ones too: temporaries start with a dot) and its bytes.
QMap<QString, QByteArray> folder_bytes(const QString& folder)
{
  QMap<QString, QByteArray> files;
  for (const QString& name : QDir(folder).entryList(QDir::Files | QDir::Hidden, QDir::Name))
    files[name] = file_bytes(folder + "/" + name);
  return files;
}

//! Keeps every worker of Qt's global thread pool busy while it lives: work
//! QtConcurrent starts meanwhile waits in the queue.
class PoolHold
{
public:
  PoolHold()
  {
    QThreadPool* pool = QThreadPool::globalInstance();
    workers_ = pool->maxThreadCount();
    for (int k = 0; k < workers_; ++k)
      pool->start([this] {
        started_.release();
        release_.acquire();
        ended_.release();
      });
    started_.acquire(workers_);
  }
  ~PoolHold()
  {
    release_.release(workers_);
    ended_.acquire(workers_); // the workers are done with the semaphores
  }

private:
  int workers_ = 0;
  QSemaphore started_, release_, ended_;
};

//! Counts the turns of the event loop while it runs.
struct LoopTicks
{
  LoopTicks()
  {
    timer.setInterval(0);
    QObject::connect(&timer, &QTimer::timeout, [this] { ++ticks; });
    timer.start();
  }
  QTimer timer;
  int ticks = 0;
};

//! Runs `meshpaint ARGS`; its exit code.
QString write_file(const QString& path, const QString& text)
{
  QFile f(path);
  if (!f.open(QIODevice::WriteOnly))
    qFatal("cannot write %s", qPrintable(path));
  f.write(text.toUtf8());
  return path;
}

int run_meshpaint(const QStringList& args)
{
  QProcess p;
  p.start(MESHPAINT_BIN, args);
  p.waitForFinished(600000);
  if (p.exitCode() != 0)
    qWarning("%s", p.readAllStandardError().constData());
  return p.exitCode();
}

//! `meshpaint paint MESH ARGS --strokes SESSION/strokes.json -o OUT`; what
//! differs between OUT/surface.vtp and SESSION/surface.vtp ("" when every
//! channel array is equal bit for bit).
QString replay_differs(const QString& session, const QStringList& mesh_and_args, const QString& out)
{
  if (run_meshpaint(QStringList{"paint"} + mesh_and_args +
                    QStringList{"--strokes", session + "/strokes.json", "-o", out, "--quiet"}) != 0)
    return "the replay failed";
  const auto live = read_vtp(session + "/surface.vtp"), again = read_vtp(out + "/surface.vtp");
  if (live->GetNumberOfPoints() != again->GetNumberOfPoints())
    return "points differ";
  for (const char* name : {"diffuse", "label", "specular", "roughness", "displacement", "mask"}) {
    vtkDataArray *a = live->GetPointData()->GetArray(name), *b = again->GetPointData()->GetArray(name);
    if (!a || !b || a->GetDataSize() != b->GetDataSize() ||
        std::memcmp(a->GetVoidPointer(0), b->GetVoidPointer(0), std::size_t(a->GetDataSize()) * 4) != 0)
      return name;
  }
  return QString();
}

//! Class 3 "defect" added, and a label stroke of it across the middle.
bool label_a_defect(StudioWindow& w, vtkPaintView* view)
{
  if (!view->AddLabelClass(3, "defect", 1, 0.5, 0))
    return false;
  QTest::keyClick(w.render_widget(), Qt::Key_T, Qt::ShiftModifier); // the label tool
  QTest::keyClick(w.render_widget(), Qt::Key_3);
  const std::size_t before = view->GetScene().history().size();
  drag(w.render_widget(), {0.35, 0.45}, {0.65, 0.55});
  return view->GetScene().history().size() == before + 1;
}

} // namespace

class StudioTest : public QObject
{
  Q_OBJECT

private Q_SLOTS:
  void drag_paints_on_meshes_wound_either_way()
  {
    QTemporaryDir dir;
    for (const QString& mesh : {kCube, inward_cube(dir)}) {
      vtkNew<vtkPaintView> view;
      auto w = open_studio(view, mesh, dir.filePath("session"));
      // The front face (z = 1, towards the camera) as imported: its normal
      // points out of the cube, or into the open box.
      const meshpaint::BaseMesh& base = view->GetScene().surface(0).atlas().base_mesh();
      for (std::size_t f = 0; f < base.face_count(); ++f) {
        const int* v = &base.face_vertices[std::size_t(base.face_offsets[f])];
        const meshpaint::Vec3 &a = base.points[std::size_t(v[0])], &b = base.points[std::size_t(v[1])],
                              &c = base.points[std::size_t(v[2])];
        if (a[2] == 1.f && b[2] == 1.f && c[2] == 1.f) {
          const float z = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
          QVERIFY2(mesh == kCube ? z > 0 : z < 0, qPrintable(mesh));
        }
      }
      drag(w->render_widget(), {0.4, 0.45}, {0.6, 0.55});
      QCOMPARE(int(view->GetScene().history().size()), 1);
      QVERIFY2(view->GetScene().history()[0].points.size() >= 5, qPrintable(mesh)); // went on with the drag
      QVERIFY2(red_texels(view) > 5, qPrintable(mesh));
    }
  }

  void a_failure_while_dragging_says_why()
  {
    // A sculpt at edit level 1 under a memory cap that holds the painting
    // but not the multiresolution layers: the first dabs, mid-drag, are
    // refused, and the status line says why after the button is let go.
    QTemporaryDir dir;
    std::size_t cap = 0;
    {
      vtkNew<vtkPaintView> plain;
      plain->SetLevel(4);
      QVERIFY(plain->LoadMesh(kCube.toStdString().c_str()));
      const meshpaint::Atlas& atlas = plain->GetScene().surface(0).atlas();
      const meshpaint::DeviceInfo& device = atlas.shared_runtime()->info();
      const std::size_t painting = meshpaint::painting_bytes(atlas.topology(), 4, atlas.storage());
      cap = (painting + meshpaint::coarse_edits_bytes(atlas.topology(), 4, atlas.storage(), device)) / 2;
    }
    qputenv("MESHPAINT_DEVICE_MEMORY", QByteArray::number(qulonglong(cap)));
    vtkNew<vtkPaintView> view;
    auto w = open_studio(view, kCube, dir.filePath("session"));
    qunsetenv("MESHPAINT_DEVICE_MEMORY");
    view->GetBrush()->set_tool("sculpt");
    view->GetBrush()->set_edit_level(1);
    const std::vector<meshpaint::Float4> unchanged = view->GetScene().surface(0).atlas().read_positions(4);
    drag(w->render_widget(), {0.4, 0.45}, {0.6, 0.55});
    // Taken back: no step in the history, whose replay would sculpt.
    QVERIFY(view->GetScene().history().empty());
    QVERIFY(view->GetScene().undone().empty()); // nor one to redo
    QVERIFY(view->GetScene().surface(0).atlas().read_positions(4) == unchanged);
    QVERIFY(!view->IsPainting());
    const QString message = view->GetMessage();
    QVERIFY2(message.startsWith("editing below painting level 4 needs"), qPrintable(message));
    QCOMPARE(QString(view->GetLastError()), message);
    // The surface is as it was, and the next stroke at the painting level paints.
    view->GetBrush()->set_edit_level(4);
    drag(w->render_widget(), {0.4, 0.45}, {0.6, 0.55});
    QVERIFY2(view->GetScene().history().size() == 1, view->GetMessage());
    QVERIFY(view->GetScene().surface(0).atlas().read_positions(4) != unchanged);
    QCOMPARE(QString(view->GetMessage()), QString());
  }

  void a_label_class_chosen_in_the_list_paints_its_id_in_its_colour()
  {
    QTemporaryDir dir;
    vtkNew<vtkPaintView> view;
    auto w = open_studio(view, kCube, dir.filePath("session"));
    QVERIFY(view->AddLabelClass(2, "bone", 0.9, 0.9, 0.2));
    QVERIFY(view->AddLabelClass(5, "lesion", 0.1, 0.2, 1.0));
    QTableWidget* table = w->label_panel()->table();
    QCOMPARE(table->rowCount(), 2);
    const QColor blue = QColor::fromRgbF(0.1, 0.2, 1.0);
    QCOMPARE(pixels_like(*w, blue), 0);
    // Choose "lesion" in the list with the mouse.
    const QRect cell = table->visualItemRect(table->item(1, 3));
    QTest::mouseClick(table->viewport(), Qt::LeftButton, Qt::NoModifier, cell.center());
    QCOMPARE(QString::fromStdString(view->GetBrush()->tool()), QString("label"));
    QCOMPARE(view->GetBrush()->label(), 5);
    QCOMPARE(QString(view->GetShownChannel()), QString("label"));
    drag(w->render_widget(), {0.4, 0.45}, {0.6, 0.55});
    std::size_t fives = 0;
    for (const meshpaint::Float4& m : view->GetScene().surface(0).read_channels().material)
      fives += m[2] == 5.f;
    QVERIFY(fives > 5);
    // The live area per class: the painted class has some, the other none.
    QVERIFY(table->item(1, 5)->text().toDouble() > 0.0);
    QCOMPARE(table->item(0, 5)->text().toDouble(), 0.0);
    view->Render();
    QVERIFY(pixels_like(*w, blue) > 200);
    // Hidden, the class shows as unlabelled surface.
    QTableWidgetItem* shown = table->item(1, 0);
    QTest::mouseClick(table->viewport(), Qt::LeftButton, Qt::NoModifier, table->visualItemRect(shown).center());
    shown->setCheckState(Qt::Unchecked); // the check box itself, as a click on it does
    QVERIFY(!view->GetLabelClassVisible(5));
    QCOMPARE(pixels_like(*w, blue), 0);
  }

  void the_label_panel_locks_fills_picks_and_merges()
  {
    QTemporaryDir dir;
    vtkNew<vtkPaintView> view;
    auto w = open_studio(view, kCube, dir.filePath("session"));
    meshpaint::studio::LabelPanel* panel = w->label_panel();
    QTableWidget* table = panel->table();
    QVERIFY(view->AddLabelClass(2, "bone", 0.9, 0.9, 0.2));
    QVERIFY(view->AddLabelClass(5, "lesion", 0.1, 0.2, 1.0));
    panel->sync();
    QWidget* render = w->render_widget();
    for (int k = 0; k < 4; ++k) // a brush wide enough that the fill's click lands well inside the stroke
      QTest::keyClick(render, Qt::Key_BracketRight);
    const auto click_cell = [&](int row, int column) {
      QTest::mouseClick(table->viewport(), Qt::LeftButton, Qt::NoModifier,
                        table->visualItemRect(table->item(row, column)).center());
    };
    const auto labels = [&] {
      std::vector<float> out;
      for (const meshpaint::Float4& m : view->GetScene().surface(0).read_channels().material)
        out.push_back(m[2]);
      return out;
    };
    const auto count = [](const std::vector<float>& l, float id) { return std::count(l.begin(), l.end(), id); };
    // Paint "lesion", lock it, then paint "bone" across it.
    click_cell(1, 3);
    drag(render, {0.4, 0.45}, {0.6, 0.55});
    const std::vector<float> lesion = labels();
    QVERIFY(count(lesion, 5.f) > 5);
    click_cell(1, 1);
    table->item(1, 1)->setCheckState(Qt::Checked); // the check box itself, as a click on it does
    QCOMPARE(view->GetBrush()->locked_labels(), std::vector<int>{5});
    click_cell(0, 3);
    QCOMPARE(view->GetBrush()->label(), 2);
    drag(render, {0.3, 0.5}, {0.7, 0.5}); // across the lesion
    const std::vector<float> locked = labels();
    QVERIFY(count(locked, 2.f) > 5); // the bone went on both sides
    for (std::size_t t = 0; t < lesion.size(); ++t)
      if (lesion[t] == 5.f)
        QCOMPARE(locked[t], 5.f);
    QCOMPARE(view->GetScene().history().back().paint().locked_labels, std::vector<int>{5});
    if (const QByteArray shots = qgetenv("MESHPAINT_STUDIO_SHOTS"); !shots.isEmpty()) // pictures for the guide
      w->grab().save(QString(shots) + "/studio_label_tools.png");
    // A fill on the lesion while it is locked changes nothing; unlocked,
    // the whole lesion becomes bone.
    QTest::mouseClick(panel->fill_button(), Qt::LeftButton);
    QVERIFY(panel->fill_button()->isChecked());
    const QPoint centre(render->width() / 2, render->height() / 2);
    QTest::qWait(20); // the item buffer is captured at rest
    QTest::mouseClick(render, Qt::LeftButton, Qt::NoModifier, centre);
    QCOMPARE(view->GetScene().history().back().tool, meshpaint::Tool::Fill);
    QVERIFY(labels() == locked);
    table->item(1, 1)->setCheckState(Qt::Unchecked);
    QVERIFY(view->GetBrush()->locked_labels().empty());
    QTest::qWait(20); // the item buffer is captured at rest
    QTest::mouseClick(render, Qt::LeftButton, Qt::NoModifier, centre);
    const std::vector<float> filled = labels();
    QCOMPARE(int(count(filled, 5.f)), 0);
    QVERIFY(count(filled, 2.f) >= count(lesion, 5.f));
    QTest::mouseClick(panel->fill_button(), Qt::LeftButton);
    QVERIFY(!panel->fill_button()->isChecked());
    // The eyedropper: the button picks the class under a click, the key e
    // the colour under the mouse for the paint tool.
    view->GetBrush()->set_label(9);
    QTest::mouseClick(panel->pick_button(), Qt::LeftButton);
    QTest::qWait(20); // the item buffer is captured at rest
    QTest::mouseClick(render, Qt::LeftButton, Qt::NoModifier, centre);
    QCOMPARE(view->GetBrush()->label(), 2);
    QVERIFY(!panel->pick_button()->isChecked());
    view->GetBrush()->set_tool("paint");
    view->GetBrush()->set_colour({0.0, 0.0, 1.0});
    mouse(render, QEvent::MouseMove, {render->width() / 8, render->height() / 2}, Qt::NoButton, Qt::NoButton);
    mouse(render, QEvent::MouseMove, centre, Qt::NoButton, Qt::NoButton);
    QTest::keyClick(render, Qt::Key_E);
    const std::array<double, 3> picked = view->GetBrush()->colour();
    QVERIFY2(std::abs(picked[0] - 0.8) < 0.01 && std::abs(picked[2] - 0.8) < 0.01, view->GetMessage()); // the unpainted grey
    const int history = int(view->GetScene().history().size());
    // Paint only over unlabelled surface: a stroke across the bone keeps it.
    click_cell(1, 3);
    panel->only_over()->setCurrentIndex(panel->only_over()->findData(0));
    Q_EMIT panel->only_over()->activated(panel->only_over()->currentIndex());
    QCOMPARE(view->GetBrush()->only_over_label(), 0);
    drag(render, {0.5, 0.3}, {0.5, 0.7}); // across the bone
    const std::vector<float> over = labels();
    for (std::size_t t = 0; t < over.size(); ++t)
      if (filled[t] == 2.f)
        QCOMPARE(over[t], 2.f);
    QVERIFY(count(over, 5.f) > 0);
    // Merge: bone into lesion; bone leaves the table.
    click_cell(0, 3);
    panel->merge_into()->setCurrentIndex(panel->merge_into()->findData(5));
    QTest::mouseClick(panel->merge_button(), Qt::LeftButton);
    QCOMPARE(int(view->GetScene().history().size()), history + 2);
    QCOMPARE(view->GetScene().history().back().tool, meshpaint::Tool::Merge);
    QCOMPARE(int(count(labels(), 2.f)), 0);
    QCOMPARE(table->rowCount(), 1);
    // Undo brings bone's surface and its entry back, redo takes them away again.
    QTest::keyClick(w->render_widget(), Qt::Key_Z, Qt::ControlModifier);
    QVERIFY(count(labels(), 2.f) > 0);
    QCOMPARE(table->rowCount(), 2);
    QVERIFY(!table->findItems("bone", Qt::MatchExactly).isEmpty());
    QTest::keyClick(w->render_widget(), Qt::Key_Y, Qt::ControlModifier);
    QCOMPARE(int(count(labels(), 2.f)), 0);
    QCOMPARE(table->rowCount(), 1);
    // The recording replays to the same bits.
    QVERIFY(view->Save());
    const QString replayed = dir.filePath("replayed");
    QProcess paint;
    paint.start(MESHPAINT_BIN, {"paint", kCube, "--strokes", dir.filePath("session/strokes.json"), "-o", replayed, "--quiet"});
    QVERIFY(paint.waitForFinished(120000));
    QCOMPARE(paint.exitCode(), 0);
    vtkSmartPointer<vtkPolyData> a = read_vtp(dir.filePath("session/surface.vtp")), b = read_vtp(replayed + "/surface.vtp");
    vtkDataArray *la = a->GetPointData()->GetArray("label"), *lb = b->GetPointData()->GetArray("label");
    QVERIFY(la && lb && la->GetNumberOfTuples() == lb->GetNumberOfTuples());
    for (vtkIdType i = 0; i < la->GetNumberOfTuples(); ++i)
      QCOMPARE(la->GetTuple1(i), lb->GetTuple1(i));
  }

  void the_fill_key_fills_under_the_mouse_and_connects_diagonally_on_request()
  {
    QTemporaryDir dir;
    const QString session = dir.filePath("session");
    vtkNew<vtkPaintView> view;
    auto w = open_studio(view, kCube, session);
    QWidget* r = w->render_widget();
    const auto labels = [&] {
      std::vector<float> out;
      for (const meshpaint::Float4& m : view->GetScene().surface(0).read_channels().material)
        out.push_back(m[2]);
      return out;
    };
    // A band of class 2 across the front, then g over the surface with class 3 chosen.
    QTest::keyClick(r, Qt::Key_T, Qt::ShiftModifier); // the label tool
    QTest::keyClick(r, Qt::Key_2);
    drag(r, {0.5, 0.4}, {0.5, 0.6});
    const std::vector<float> banded = labels();
    QTest::keyClick(r, Qt::Key_3);
    QTest::qWait(20);
    mouse(r, QEvent::MouseMove, QPoint(r->width() / 8, r->height() / 2), Qt::NoButton, Qt::NoButton);
    mouse(r, QEvent::MouseMove, QPoint(r->width() * 4 / 10, r->height() / 2), Qt::NoButton, Qt::NoButton);
    QVERIFY(!w->label_panel()->fill_diagonals()->isChecked());
    QTest::keyClick(r, Qt::Key_G);
    QVERIFY2(view->GetScene().history().size() == 2,
             qPrintable(QString("%1 strokes: %2").arg(view->GetScene().history().size()).arg(view->GetMessage())));
    QCOMPARE(view->GetScene().history().back().tool, meshpaint::Tool::Fill);
    QVERIFY(!view->GetScene().history().back().paint().fill_diagonals);
    std::vector<float> filled = labels();
    std::size_t threes = 0;
    for (std::size_t t = 0; t < filled.size(); ++t) {
      QVERIFY(filled[t] == (banded[t] == 2.f ? 2.f : 3.f) || (banded[t] == 0.f && filled[t] == 0.f));
      threes += filled[t] == 3.f;
    }
    QVERIFY(threes > filled.size() / 4);
    // G: fills connect across corners (the panel's box follows), g again with class 4.
    QTest::keyClick(r, Qt::Key_G, Qt::ShiftModifier);
    QVERIFY(view->GetBrush()->fill_diagonals());
    QVERIFY(w->label_panel()->fill_diagonals()->isChecked());
    QTest::keyClick(r, Qt::Key_4);
    QTest::keyClick(r, Qt::Key_G);
    QCOMPARE(int(view->GetScene().history().size()), 3);
    QVERIFY(view->GetScene().history().back().paint().fill_diagonals);
    filled = labels();
    for (std::size_t t = 0; t < filled.size(); ++t)
      if (banded[t] != 2.f)
        QVERIFY(filled[t] == 4.f || filled[t] == 0.f);
    // The box unticked: the brush's fills go along sides again.
    QTest::mouseClick(w->label_panel()->fill_diagonals(), Qt::LeftButton);
    QVERIFY(!view->GetBrush()->fill_diagonals());
    // The recording replays the fills to the same labels.
    QTest::keyClick(r, Qt::Key_S, Qt::ControlModifier);
    QFile recording(session + "/strokes.json");
    QVERIFY(recording.open(QIODevice::ReadOnly));
    QVERIFY(recording.readAll().contains("\"connect\": \"diagonals\""));
    const QString differs = replay_differs(session, {kCube}, dir.filePath("replay"));
    QVERIFY2(differs.isEmpty(), qPrintable(differs));
  }

  void the_history_list_undoes_and_redoes()
  {
    QTemporaryDir dir;
    vtkNew<vtkPaintView> view;
    auto w = open_studio(view, kCube, dir.filePath("session"));
    drag(w->render_widget(), {0.35, 0.4}, {0.5, 0.45});
    QTest::keyClick(w->render_widget(), Qt::Key_6); // the blue swatch, through the window's keys
    drag(w->render_widget(), {0.5, 0.55}, {0.65, 0.6});
    QListWidget* list = w->history_panel()->list();
    QCOMPARE(list->count(), 3); // unpainted, stroke 1, stroke 2
    const std::size_t both = red_texels(view);
    QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::NoModifier, list->visualItemRect(list->item(0)).center());
    QCOMPARE(int(view->GetScene().history().size()), 0);
    QCOMPARE(red_texels(view), std::size_t(0));
    QCOMPARE(list->count(), 3); // the undone strokes stay listed, to redo
    QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::NoModifier, list->visualItemRect(list->item(2)).center());
    QCOMPARE(int(view->GetScene().history().size()), 2);
    QCOMPARE(red_texels(view), both);
    QTest::keyClick(w->render_widget(), Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(int(view->GetScene().history().size()), 1);
  }

  void a_saved_session_reopens_and_replays_to_the_same_bits()
  {
    QTemporaryDir dir;
    const QString session = dir.filePath("session");
    vtkNew<vtkPaintView> view;
    auto w = open_studio(view, kCube, session);
    drag(w->render_widget(), {0.35, 0.4}, {0.6, 0.55});
    QTest::keyClick(w->render_widget(), Qt::Key_T, Qt::ShiftModifier); // the label tool
    QTest::keyClick(w->render_widget(), Qt::Key_3);
    drag(w->render_widget(), {0.45, 0.6}, {0.55, 0.35});
    QTest::keyClick(w->render_widget(), Qt::Key_S, Qt::ControlModifier); // save: strokes.json, surface.vtp
    QVERIFY(QFile::exists(session + "/strokes.json"));
    const QString project = dir.filePath("cube.meshpaint");
    QVERIFY(w->save_project(project));
    const QString differs = replay_differs(session, {kCube}, dir.filePath("replay"));
    QVERIFY2(differs.isEmpty(), qPrintable(differs));
    // Reopened, the project has the painted channels.
    const std::vector<meshpaint::Float4> before = view->GetScene().surface(0).read_channels().diffuse;
    QVERIFY(w->open_path(project));
    const std::vector<meshpaint::Float4> after = view->GetScene().surface(0).read_channels().diffuse;
    QCOMPARE(after.size(), before.size());
    QVERIFY(std::memcmp(after.data(), before.data(), before.size() * sizeof(meshpaint::Float4)) == 0);
  }

  void q_closes_the_window()
  {
    QTemporaryDir dir;
    vtkNew<vtkPaintView> view;
    auto w = open_studio(view, kCube, dir.filePath("session"));
    QTest::keyClick(w->render_widget(), Qt::Key_Q);
    QTRY_VERIFY(!w->isVisible());
  }

  void the_fit_dialog_runs_and_cancels()
  {
    QTemporaryDir dir;
    vtkNew<vtkPaintView> view;
    auto w = open_studio(view, kCube, dir.filePath("session"));
    w->set_program(MESHPAINT_BIN);
    // A fit of the bunny scan takes seconds: Cancel stops it, and nothing is written.
    const QString bunny = QString(MESHPAINT_SOURCE_DIR) + "/data/scans/bunny00.off";
    if (QFile::exists(bunny)) {
      bool finished = false, fitted = true;
      meshpaint::studio::FitDialog dialog(MESHPAINT_BIN, bunny, dir.filePath("bunny.meshpaint"), [&](bool ok) {
        finished = true;
        fitted = ok;
      });
      dialog.show();
      dialog.start();
      QVERIFY(dialog.running());
      QTest::mouseClick(dialog.findChild<QPushButton*>("cancel"), Qt::LeftButton);
      QTRY_VERIFY_WITH_TIMEOUT(finished, 10000);
      QVERIFY(!fitted && !dialog.running());
      QVERIFY(!QFile::exists(dir.filePath("bunny.meshpaint")));
    }
    // The cube fits in a moment; the project opens in the window when done.
    const QString out = dir.filePath("cube.meshpaint");
    meshpaint::studio::FitDialog* dialog = w->fit_scan(kCube, out);
    QTRY_VERIFY_WITH_TIMEOUT(!dialog->running(), 60000);
    QVERIFY2(QFile::exists(out), qPrintable(dialog->log()));
    QTRY_VERIFY(view->GetProject() != nullptr);
    QVERIFY(dialog->log().contains("saved"));
  }

  void the_colour_panels_eyedropper_takes_the_colour_under_a_click()
  {
    QTemporaryDir dir;
    vtkNew<vtkPaintView> view;
    auto w = open_studio(view, kCube, dir.filePath("session"));
    drag(w->render_widget(), {0.4, 0.45}, {0.6, 0.55}); // red
    w->brush_panel()->set_colour(QColor::fromRgbF(0.0, 0.0, 1.0));
    view->GetBrush()->set_tool("label"); // the colour's eyedropper picks a colour all the same
    QPushButton* eyedropper = w->brush_panel()->eyedropper();
    QTest::mouseClick(eyedropper, Qt::LeftButton);
    QVERIFY(eyedropper->isChecked());
    const QPoint centre(w->render_widget()->width() / 2, w->render_widget()->height() / 2);
    mouse(w->render_widget(), QEvent::MouseButtonPress, centre, Qt::LeftButton, Qt::LeftButton);
    mouse(w->render_widget(), QEvent::MouseButtonRelease, centre, Qt::LeftButton, Qt::NoButton);
    QVERIFY(!eyedropper->isChecked());
    QCOMPARE(int(view->GetScene().history().size()), 1); // the click painted nothing
    QCOMPARE(QString::fromStdString(view->GetBrush()->tool()), QString("paint"));
    const std::array<double, 3> c = view->GetBrush()->colour();
    QVERIFY2(c[0] > 0.8 && c[2] < 0.2, qPrintable(QString("%1 %2 %3").arg(c[0]).arg(c[1]).arg(c[2])));
  }

  void the_views_keys_work_after_a_click_on_a_panel()
  {
    QTemporaryDir dir;
    vtkNew<vtkPaintView> view;
    auto w = open_studio(view, kCube, dir.filePath("session"));
    const std::string before = view->GetBrush()->tool();
    // A button of the panels has the focus: t still changes the tool.
    QPushButton* swatch = w->brush_panel()->findChild<QPushButton*>("swatch_3");
    swatch->setFocus();
    QTest::keyClick(swatch, Qt::Key_T);
    QVERIFY(view->GetBrush()->tool() != before);
    // The label table, not editing: v shows the next channel.
    const std::string shown = view->GetShownChannel();
    QTest::keyClick(w->label_panel()->table(), Qt::Key_V);
    QVERIFY(view->GetShownChannel() != shown);
    // A number field keeps what is typed into it.
    const std::string tool = view->GetBrush()->tool();
    auto* spin = w->brush_panel()->findChild<QAbstractSpinBox*>();
    QVERIFY(spin);
    QTest::keyClick(spin, Qt::Key_T);
    QCOMPARE(view->GetBrush()->tool(), tool);
  }

  void the_fit_log_shows_whole_lines()
  {
    // A program writing its lines in pieces, and a bar redrawn after
    // carriage returns, as a fit on a terminal draws it.
    QTemporaryDir dir;
    const QString program = write_file(dir.filePath("fit.sh"),
                                       "#!/bin/sh\n"
                                       "printf 'meshpaint fit' >&2; sleep 0.3; printf ': pass 1' >&2; sleep 0.3\n"
                                       "printf ' of 2\\n' >&2; sleep 0.3\n"
                                       "printf '\\rbar [#   ] 25%%' >&2; sleep 0.3; printf '\\rbar [####] 100%%\\033[K\\n' >&2\n"
                                       "printf 'saved'; sleep 0.3; printf ' it\\n'\n");
    QFile::setPermissions(program, QFile::permissions(program) | QFileDevice::ExeOwner);
    bool finished = false;
    meshpaint::studio::FitDialog dialog(program, kCube, dir.filePath("out.meshpaint"), [&](bool) { finished = true; });
    dialog.start();
    QTRY_VERIFY_WITH_TIMEOUT(finished, 10000);
    QCOMPARE(dialog.log(), QString("meshpaint fit: pass 1 of 2\nbar [####] 100%\nsaved it"));
  }

  void ctrl_e_exports_off_the_interface_thread()
  {
    QTemporaryDir dir;
    const QString session = dir.filePath("session");
    vtkNew<vtkPaintView> view;
    auto w = open_studio(view, kCube, session);
    drag(w->render_widget(), {0.4, 0.45}, {0.6, 0.55});
    const std::size_t red = red_texels(view);
    LoopTicks loop;
    QTest::keyClick(w->render_widget(), Qt::Key_E, Qt::ControlModifier);
    // Back from the key at once, the export still running: not done in the key's handler.
    QVERIFY(w->busy());
    QVERIFY(view->GetLocked());
    // Meanwhile no stroke starts on the surface (it is being read), and undo is refused.
    const int cx = w->render_widget()->width() / 2, cy = w->render_widget()->height() / 2;
    QCOMPARE(view->BeginStroke(cx, cy), 0);
    QCOMPARE(view->Undo(), 0);
    QTRY_VERIFY_WITH_TIMEOUT(!w->busy(), 120000);
    QVERIFY(loop.ticks > 0);
    QVERIFY(!view->GetLocked());
    QCOMPARE(int(view->GetScene().history().size()), 1);
    QCOMPARE(red_texels(view), red);
    drag(w->render_widget(), {0.3, 0.6}, {0.6, 0.3}); // unlocked again: it paints
    QCOMPARE(int(view->GetScene().history().size()), 2);
    // Every file written whole under its name, no temporary left beside them.
    const QStringList files = QDir(session).entryList(QDir::Files, QDir::Name);
    for (const char* name : {"model.obj", "model.mtl", "model.gltf", "diffuse.png", "specular.png"})
      QVERIFY2(files.contains(name), qPrintable(files.join(' ')));
    for (const QString& f : files)
      QVERIFY2(!f.contains("tmp") && !f.startsWith('.'), qPrintable(f));
    // glTF from the menu's path: a binary glTF file.
    meshpaint::studio::BackgroundTask* task = w->export_gltf(dir.filePath("cube.glb"));
    QVERIFY(task != nullptr);
    QVERIFY(w->export_model() == nullptr); // one at a time
    QTRY_VERIFY_WITH_TIMEOUT(!w->busy(), 120000);
    QFile glb(dir.filePath("cube.glb"));
    QVERIFY(glb.open(QIODevice::ReadOnly));
    QCOMPARE(glb.read(4), QByteArray("glTF"));
  }

  void a_cancelled_export_leaves_the_previous_files_whole()
  {
    QTemporaryDir dir;
    const QString session = dir.filePath("session");
    vtkNew<vtkPaintView> view;
    auto w = open_studio(view, kCube, session);
    drag(w->render_widget(), {0.4, 0.45}, {0.6, 0.55});
    QTest::keyClick(w->render_widget(), Qt::Key_E, Qt::ControlModifier);
    QTRY_VERIFY_WITH_TIMEOUT(!w->busy(), 120000);
    const QString glb = dir.filePath("cube.glb");
    QVERIFY(w->export_gltf(glb) != nullptr);
    QTRY_VERIFY_WITH_TIMEOUT(!w->busy(), 120000);
    const QMap<QString, QByteArray> before = folder_bytes(session);
    const QByteArray glb_before = file_bytes(glb);
    QVERIFY(before.contains("model.obj") && before.contains("diffuse.png") && !glb_before.isEmpty());
    // A second stroke: a finished export now writes other maps.
    drag(w->render_widget(), {0.3, 0.6}, {0.6, 0.3});
    // The work waits for a worker while the pool's are held, so the Cancel
    // button is pressed before it ends, however quick it is.
    std::unique_ptr<PoolHold> hold;
    const auto cancel_now = [&] {
      QVERIFY(w->busy());
      QProgressDialog* dialog = w->task()->dialog();
      dialog->show(); // it shows by itself after a moment; the click comes before that
      QPushButton* cancel = dialog->findChild<QPushButton*>();
      QVERIFY2(cancel, qPrintable(dialog->labelText()));
      QTest::mouseClick(cancel, Qt::LeftButton);
      hold.reset();
      QTRY_VERIFY_WITH_TIMEOUT(!w->busy(), 120000);
      QVERIFY(!view->GetLocked());
      QVERIFY2(w->statusBar()->currentMessage() == "cancelled", qPrintable(w->statusBar()->currentMessage()));
      hold = std::make_unique<PoolHold>();
    };
    hold = std::make_unique<PoolHold>();
    // Ctrl+E, cancelled: every file as before, no temporary beside them.
    QTest::keyClick(w->render_widget(), Qt::Key_E, Qt::ControlModifier);
    cancel_now();
    QCOMPARE(folder_bytes(session), before);
    // The glTF file, cancelled: as before.
    QVERIFY(w->export_gltf(glb) != nullptr);
    cancel_now();
    QCOMPARE(file_bytes(glb), glb_before);
    // Into folders and files that were not there: none appears.
    view->SetSaveDirectory(dir.filePath("new/session").toStdString().c_str());
    QTest::keyClick(w->render_widget(), Qt::Key_E, Qt::ControlModifier);
    cancel_now();
    QVERIFY(!QFileInfo::exists(dir.filePath("new")));
    QVERIFY(w->export_gltf(dir.filePath("new.gltf")) != nullptr);
    cancel_now();
    const QString scan = dir.filePath("scan.ply");
    QCOMPARE(run_meshpaint({"subdivide", kCube, "--level", "3", "--quiet", "-o", scan}), 0);
    QVERIFY(w->export_labelled_scan(scan, dir.filePath("labelled.vtp")) != nullptr);
    cancel_now();
    hold.reset();
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden | QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name),
             QStringList({"cube.glb", "scan.ply", "session"}));
    // Not cancelled, the same export writes the second stroke's maps.
    view->SetSaveDirectory(session.toStdString().c_str());
    QTest::keyClick(w->render_widget(), Qt::Key_E, Qt::ControlModifier);
    QTRY_VERIFY_WITH_TIMEOUT(!w->busy(), 120000);
    const QMap<QString, QByteArray> after = folder_bytes(session);
    QCOMPARE(after.keys(), before.keys());
    QVERIFY(after["diffuse.png"] != before["diffuse.png"]);
  }

  void the_level_panel_changes_the_level_in_the_background()
  {
    QTemporaryDir dir;
    vtkNew<vtkPaintView> view;
    auto w = open_studio(view, kCube, dir.filePath("session"));
    drag(w->render_widget(), {0.4, 0.45}, {0.6, 0.55});
    QCOMPARE(view->GetLevel(), 4);
    const vtkIdType faces = view->GetFaceCount();
    meshpaint::studio::LevelPanel* panel = w->level_panel();
    // Cancelled, the scene stays as it was.
    panel->level()->setValue(5);
    QTest::mouseClick(panel->apply(), Qt::LeftButton);
    QVERIFY(w->busy());
    w->task()->cancel();
    QTRY_VERIFY_WITH_TIMEOUT(!w->busy(), 120000);
    QCOMPARE(view->GetLevel(), 4);
    QCOMPARE(view->GetFaceCount(), faces);
    // Applied: level 3, a quarter of the quads, the stroke painted again on them.
    panel->level()->setValue(3);
    QTest::mouseClick(panel->apply(), Qt::LeftButton);
    QVERIFY(w->busy());
    QTRY_VERIFY_WITH_TIMEOUT(!w->busy(), 120000);
    QCOMPARE(view->GetLevel(), 3);
    QCOMPARE(view->GetFaceCount(), faces / 4);
    QCOMPARE(int(view->GetScene().history().size()), 1);
    QVERIFY(red_texels(view) > 0);
    QCOMPARE(view->GetBrush()->edit_level(), 3);
    // The edit level from the panel reaches the brush.
    panel->findChild<QSpinBox*>("edit_level")->setValue(2);
    QCOMPARE(view->GetBrush()->edit_level(), 2);
    // Level of detail: "off" draws the painting level while moving.
    auto* lod = panel->findChild<QComboBox*>("lod");
    lod->setCurrentIndex(1);
    Q_EMIT lod->activated(1);
    QCOMPARE(view->GetLodLevel(), 0);
    QCOMPARE(view->GetLodLevelInUse(), 3);
    // Still paints after the change.
    drag(w->render_widget(), {0.35, 0.6}, {0.6, 0.35});
    QCOMPARE(int(view->GetScene().history().size()), 2);
  }

  void a_projects_level_changes_and_saves_at_the_new_level()
  {
    QTemporaryDir dir;
    vtkNew<vtkPaintView> view;
    auto w = open_studio(view, kCube, dir.filePath("first"));
    // A project of the cube at level 4 with a class and a label stroke.
    QVERIFY(label_a_defect(*w, view));
    const QString project = dir.filePath("cube.meshpaint");
    QVERIFY(w->save_project(project));
    // Opened, painted on, then changed to level 3 with the Level panel.
    QVERIFY(w->open_path(project));
    const QString session = dir.filePath("session");
    view->SetSaveDirectory(session.toStdString().c_str());
    QCOMPARE(int(view->GetScene().history().size()), 0);
    for (int k = 0; k < 3; ++k) // the new surface's brush: wider than its texel spacing, as open_studio's
      QTest::keyClick(w->render_widget(), Qt::Key_BracketRight);
    drag(w->render_widget(), {0.42, 0.52}, {0.58, 0.45});
    QVERIFY2(view->GetScene().history().size() == 1, view->GetMessage());
    const vtkIdType faces = view->GetFaceCount();
    meshpaint::studio::LevelPanel* panel = w->level_panel();
    QVERIFY(panel->apply()->isEnabled() || panel->level()->value() == 4);
    panel->level()->setValue(3);
    QVERIFY(panel->apply()->isEnabled());
    QTest::mouseClick(panel->apply(), Qt::LeftButton);
    QVERIFY(w->busy());
    QTRY_VERIFY_WITH_TIMEOUT(!w->busy(), 120000);
    QCOMPARE(view->GetLevel(), 3);
    QCOMPARE(view->GetFaceCount(), faces / 4);
    // Still the project, its class kept; the project's stroke and this session's replayed.
    QVERIFY(view->GetProject() != nullptr);
    QCOMPARE(view->GetProject()->level, 3);
    QCOMPARE(int(view->GetLabelClasses().size()), 1);
    QCOMPARE(view->GetLabelClasses()[0].name, std::string("defect"));
    QCOMPARE(int(view->GetScene().history().size()), 2);
    QCOMPARE(view->GetScene().history()[0].tool, meshpaint::Tool::Label);
    const std::vector<meshpaint::Float4> material = view->GetScene().surface(0).read_channels().material;
    QVERIFY(std::count_if(material.begin(), material.end(), [](const meshpaint::Float4& m) { return m[2] == 3.f; }) > 0);
    QVERIFY(red_texels(view) > 0);
    // Saved (Ctrl+S, and over the project itself), then reopened: level 3, the class and the labels.
    QTest::keyClick(w->render_widget(), Qt::Key_S, Qt::ControlModifier);
    QVERIFY(QFile::exists(session + "/surface.meshpaint"));
    QVERIFY2(w->save_project(project), view->GetLastError());
    const std::vector<meshpaint::Float4> diffuse = view->GetScene().surface(0).read_channels().diffuse;
    QVERIFY(w->open_path(project));
    QCOMPARE(view->GetLevel(), 3);
    QCOMPARE(view->GetProject()->level, 3);
    QCOMPARE(int(view->GetLabelClasses().size()), 1);
    QCOMPARE(view->GetLabelClasses()[0].id, 3);
    const meshpaint::PaintChannels reopened = view->GetScene().surface(0).read_channels();
    QVERIFY(reopened.material.size() == material.size() &&
            std::memcmp(reopened.material.data(), material.data(), material.size() * sizeof(meshpaint::Float4)) == 0);
    QVERIFY(std::memcmp(reopened.diffuse.data(), diffuse.data(), diffuse.size() * sizeof(meshpaint::Float4)) == 0);
    // The recording (both strokes, at level 3) replays on the mesh to the same bits.
    const QString differs = replay_differs(session, {kCube, "--level", "3"}, dir.filePath("replay"));
    QVERIFY2(differs.isEmpty(), qPrintable(differs));
  }

  void a_view_wider_than_the_screen_keeps_the_window_on_it_with_its_panels()
  {
    QTemporaryDir dir;
    vtkNew<vtkPaintView> view;
    view->SetLevel(4);
    view->SetSize(3000, 2000); // --size 3000x2000
    view->SetSaveDirectory(dir.filePath("session").toStdString().c_str());
    QVERIFY(view->LoadMesh(kCube.toStdString().c_str()));
    const QRect screen = QGuiApplication::primaryScreen()->availableGeometry();
    QVERIFY(3000 + 640 > screen.width() && 2000 + 90 > screen.height()); // else this shows nothing
    StudioWindow w(view);
    QVERIFY(w.ready());
    w.show();
    QApplication::setActiveWindow(&w);
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    w.grab().save(dir.filePath("wide.png"));
    if (const char* shots = std::getenv("MESHPAINT_STUDIO_SHOTS"))
      w.grab().save(QString(shots) + "/studio_small_screen.png");
    QVERIFY2(w.frameGeometry().width() <= screen.width() && w.frameGeometry().height() <= screen.height(),
             qPrintable(QString("%1x%2 on %3x%4").arg(w.width()).arg(w.height()).arg(screen.width()).arg(screen.height())));
    // Every panel shown and inside the window, the view between them.
    const QList<QDockWidget*> docks = w.findChildren<QDockWidget*>();
    QCOMPARE(docks.size(), 5);
    for (QDockWidget* d : docks) {
      QVERIFY2(d->isVisible() && d->width() > 100, qPrintable(d->windowTitle()));
      QVERIFY2(w.rect().contains(d->geometry()), qPrintable(d->windowTitle()));
    }
    QWidget* r = w.render_widget();
    QVERIFY(r->width() > 100 && r->height() > 100);
    // The view paints where it is: the left-drag over the cube is a stroke.
    for (int k = 0; k < 3; ++k)
      QTest::keyClick(r, Qt::Key_BracketRight);
    drag(r, {0.45, 0.5}, {0.55, 0.48});
    QCOMPARE(int(view->GetScene().history().size()), 1);
  }

  void the_display_panel_chooses_the_channel_shown()
  {
    QTemporaryDir dir;
    vtkNew<vtkPaintView> view;
    auto w = open_studio(view, kCube, dir.filePath("session"));
    QComboBox* shown = w->display_panel()->shown();
    QCOMPARE(QString(view->GetShownChannel()), QString("diffuse"));
    QCOMPARE(shown->currentText(), QString("diffuse"));
    shown->setFocus();
    QTest::keyClick(shown, Qt::Key_Down); // the next channel, as a choice in the list
    QVERIFY(QString(view->GetShownChannel()) != "diffuse");
    QCOMPARE(QString(view->GetShownChannel()), shown->currentText());
    QTest::keyClick(w->render_widget(), Qt::Key_V); // the view's key: the panel follows
    QCOMPARE(shown->currentText(), QString(view->GetShownChannel()));
  }

  void patch_borders_show_over_the_surface()
  {
    QTemporaryDir dir;
    vtkNew<vtkPaintView> view;
    auto w = open_studio(view, kCube, dir.filePath("session"));
    QTest::qWait(50);
    const QColor line = QColor::fromRgbF(0.05, 0.15, 0.45);
    QCOMPARE(pixels_like(*w, line), 0);
    QVERIFY(w->patch_border_lines() == nullptr);
    QCheckBox* borders = w->display_panel()->borders();
    const QPoint box(6, borders->height() / 2); // on the box, not the empty width the layout gives it
    QTest::mouseClick(borders, Qt::LeftButton, Qt::NoModifier, box);
    QVERIFY(borders->isChecked());
    vtkPolyData* lines = w->patch_border_lines();
    QVERIFY(lines != nullptr);
    const int n = 1 << (view->GetLevel() - 1);
    QCOMPARE(lines->GetNumberOfLines(), view->GetFaceCount() / (n * n)); // one loop per patch
    QCOMPARE(lines->GetLines()->GetCellSize(0), vtkIdType(4 * n + 1));
    QTest::qWait(50);
    QVERIFY(pixels_like(*w, line) > 100);
    QTest::mouseClick(borders, Qt::LeftButton, Qt::NoModifier, box);
    QVERIFY(w->patch_border_lines() == nullptr);
  }

  void preferences_persist()
  {
    QTemporaryDir dir;
    vtkNew<vtkPaintView> view;
    auto w = open_studio(view, kCube, dir.filePath("session"));
    meshpaint::studio::PreferencesDialog* prefs = w->preferences();
    QComboBox* storage = prefs->storage();
    storage->setCurrentIndex(storage->findData("image")); // not the default of a CPU device
    QComboBox* device = prefs->device();
    QVERIFY(device->count() >= 2); // the default and at least the device painting now
    device->setCurrentIndex(1);
    const QString chosen = device->currentData().toString();
    prefs->apply();
    QCOMPARE(QString(view->GetStorage()), QString("image"));
    QCOMPARE(QString(view->GetDevice()), chosen);
    QCOMPARE(QSettings().value("storage").toString(), QString("image"));
    const meshpaint::studio::DeviceChoice saved = meshpaint::studio::preferred_device();
    QCOMPARE(QString::fromStdString(saved.storage), QString("image"));
    QCOMPARE(QString::fromStdString(saved.device), chosen);
    // A dialog opened later shows what was kept; the next surface is made with it.
    meshpaint::studio::PreferencesDialog again(view);
    QCOMPARE(again.storage()->currentData().toString(), QString("image"));
    QVERIFY(w->open_path(inward_cube(dir)));
    QCOMPARE(int(view->GetScene().surface(0).atlas().storage()), int(meshpaint::AtlasStorage::Image));
    meshpaint::studio::save_preferences({});
    QCOMPARE(QSettings().value("storage").toString(), QString());
  }

  void a_file_dropped_on_the_window_opens()
  {
    QTemporaryDir dir;
    vtkNew<vtkPaintView> view;
    auto w = open_studio(view, kCube, dir.filePath("session"));
    const QString path = inward_cube(dir);
    QMimeData data;
    data.setUrls({QUrl::fromLocalFile(path)});
    const QPoint at = w->render_widget()->geometry().center();
    QDragEnterEvent enter(at, Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(w.get(), &enter);
    QVERIFY(enter.isAccepted());
    QDropEvent drop(at, Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(w.get(), &drop);
    QVERIFY(drop.isAccepted());
    QCOMPARE(QString(view->GetObjectName(0)), QString("inward"));
    QVERIFY(w->windowTitle().contains("inward.obj"));
    // Something else than files: not taken.
    QMimeData text;
    text.setText("not a file");
    QDragEnterEvent other(at, Qt::CopyAction, &text, Qt::LeftButton, Qt::NoModifier);
    other.setAccepted(false);
    QApplication::sendEvent(w.get(), &other);
    QVERIFY(!other.isAccepted());
  }

  void a_vtps_label_classes_come_into_the_table_the_legend_and_saves()
  {
    // `meshpaint paint -o` writes the classes into surface.vtp's field data;
    // `view` adds that file as a scene's first object.
    QTemporaryDir dir;
    const QString labels = write_file(dir.filePath("labels.json"),
                                      R"([{"id": 1, "name": "nose", "colour": [0.1, 0.3, 1.0]},
                                          {"id": 4, "name": "eye region", "colour": [1.0, 0.85, 0.0]}])");
    const QString strokes = write_file(dir.filePath("s.json"), R"({"strokes": []})");
    QCOMPARE(run_meshpaint({"paint", kCube, "--strokes", strokes, "--labels", labels, "--level", "2", "--quiet", "-o",
                            dir.filePath("out")}),
             0);
    vtkNew<vtkPaintView> view;
    view->SetLevel(4);
    view->SetSaveDirectory(dir.filePath("session").toStdString().c_str());
    QVERIFY(view->AddBaseMesh(meshpaint::load_polydata_mesh(dir.filePath("out/surface.vtp").toStdString())));
    auto w = show_studio(view);
    QTableWidget* table = w->label_panel()->table();
    QCOMPARE(table->rowCount(), 2);
    QCOMPARE(table->item(0, 3)->text(), QString("nose"));
    QCOMPARE(table->item(1, 3)->text(), QString("eye region"));
    // Painted with class 4, the window shows its colour, and a save keeps the classes.
    w->label_panel()->paint_class(4);
    drag(w->render_widget(), {0.4, 0.45}, {0.6, 0.55});
    view->Render();
    QVERIFY(pixels_like(*w, QColor::fromRgbF(1.0, 0.85, 0.0)) > 200);
    QVERIFY(view->Save());
    const auto saved = read_vtp(dir.filePath("session/surface.vtp"));
    vtkAbstractArray* names = saved->GetFieldData()->GetAbstractArray("label_names");
    QVERIFY(names);
    QCOMPARE(int(names->GetNumberOfTuples()), 2);
    QCOMPARE(QString::fromStdString(names->GetVariantValue(1).ToString()), QString("eye region"));
  }

  void label_classes_load_from_a_labels_file_and_unnamed_ids_are_listed()
  {
    QTemporaryDir dir;
    vtkNew<vtkPaintView> view;
    auto w = open_studio(view, kCube, dir.filePath("session"));
    QTableWidget* table = w->label_panel()->table();
    QCOMPARE(table->rowCount(), 0);
    // Id 9 painted without a class: listed by its number, in the colour it shows in.
    view->GetBrush()->set_tool("label");
    view->GetBrush()->set_label(9);
    drag(w->render_widget(), {0.4, 0.45}, {0.6, 0.55});
    QCOMPARE(table->rowCount(), 1);
    QCOMPARE(table->item(0, 2)->text(), QString("9"));
    QCOMPARE(table->item(0, 3)->text(), QString("label 9"));
    QVERIFY(table->item(0, 5)->text().toDouble() > 0.0);
    QCOMPARE(view->GetNumberOfLabelClasses(), 0);
    // The legend lists it too, and not the unlabelled surface around it.
    const std::vector<meshpaint::LabelClass> legend =
      meshpaint::shown_label_classes(view->GetPaintedPolyData(0), view->GetLabelClasses(), {});
    QCOMPARE(int(legend.size()), 1);
    QCOMPARE(legend[0].id, 9);
    QCOMPARE(QString::fromStdString(legend[0].name), QString("label 9"));
    // Named in the table, it becomes a class.
    table->item(0, 3)->setText("scar");
    QCOMPARE(view->GetNumberOfLabelClasses(), 1);
    QCOMPARE(QString::fromStdString(view->GetLabelClasses()[0].name), QString("scar"));
    // A labels file replaces the classes (File > Load label classes...); a bad one is refused.
    const QString labels = write_file(dir.filePath("labels.json"),
                                      R"([{"id": 1, "name": "nose", "colour": [0.1, 0.3, 1.0]}])");
    QVERIFY(w->load_label_classes(labels));
    QCOMPARE(view->GetNumberOfLabelClasses(), 1);
    QCOMPARE(table->rowCount(), 2); // nose, and 9 without a class again
    QCOMPARE(table->item(0, 3)->text(), QString("nose"));
    QCOMPARE(table->item(1, 3)->text(), QString("label 9"));
    QVERIFY(!w->load_label_classes(write_file(dir.filePath("bad.json"), R"([{"id": 1}])")));
    QCOMPARE(view->GetNumberOfLabelClasses(), 1);
    QVERIFY(!w->statusBar()->currentMessage().isEmpty());
  }

  void the_labelled_scan_is_written_as_transfer_writes_it()
  {
    QTemporaryDir dir;
    vtkNew<vtkPaintView> view;
    auto w = open_studio(view, kCube, dir.filePath("session"));
    QVERIFY(label_a_defect(*w, view));
    // A scan with many vertices: the cube subdivided.
    const QString scan = dir.filePath("scan.ply");
    QCOMPARE(run_meshpaint({"subdivide", kCube, "--level", "4", "--quiet", "-o", scan}), 0);
    const QString out = dir.filePath("labelled.vtp");
    QVERIFY(w->export_labelled_scan(scan, out) != nullptr);
    QVERIFY(w->busy());
    QTRY_VERIFY_WITH_TIMEOUT(!w->busy(), 120000);
    QVERIFY(QFile::exists(out));
    // The command line on the same painting, saved as a project, writes the same labels.
    const QString project = dir.filePath("cube.meshpaint");
    QVERIFY(w->save_project(project));
    const QString cli = dir.filePath("cli.vtp");
    QCOMPARE(run_meshpaint({"transfer", project, "--to", scan, "-o", cli, "--quiet"}), 0);
    const auto mine = read_vtp(out), theirs = read_vtp(cli);
    vtkDataArray *a = mine->GetPointData()->GetArray("label"), *b = theirs->GetPointData()->GetArray("label");
    QVERIFY(a && b);
    QCOMPARE(a->GetNumberOfTuples(), theirs->GetNumberOfPoints());
    int labelled = 0;
    for (vtkIdType k = 0; k < a->GetNumberOfTuples(); ++k) {
      QCOMPARE(a->GetTuple1(k), b->GetTuple1(k));
      labelled += a->GetTuple1(k) == 3;
    }
    QVERIFY(labelled > 0);
    QVERIFY(labelled < a->GetNumberOfTuples());
    QVERIFY(mine->GetFieldData()->GetAbstractArray("label_names") != nullptr);

    // Sculpted, and written with the geometry: the scan's points move as
    // `transfer --geometry` moves them.
    view->GetBrush()->set_tool("sculpt");
    drag(w->render_widget(), {0.4, 0.5}, {0.6, 0.5});
    const QString moved = dir.filePath("moved.vtp");
    QVERIFY(w->export_labelled_scan(scan, moved, true) != nullptr);
    QTRY_VERIFY_WITH_TIMEOUT(!w->busy(), 120000);
    QVERIFY(w->save_project(project));
    const QString cli_moved = dir.filePath("cli-moved.vtp");
    QCOMPARE(run_meshpaint({"transfer", project, "--to", scan, "-o", cli_moved, "--geometry", "--quiet"}), 0);
    const auto studio_points = read_vtp(moved), cli_points = read_vtp(cli_moved);
    QCOMPARE(studio_points->GetNumberOfPoints(), cli_points->GetNumberOfPoints());
    int differ_from_labels_only = 0;
    for (vtkIdType k = 0; k < cli_points->GetNumberOfPoints(); ++k) {
      double p[3], q[3], r[3];
      studio_points->GetPoint(k, p);
      cli_points->GetPoint(k, q);
      mine->GetPoint(k, r);
      for (int c = 0; c < 3; ++c)
        QCOMPARE(p[c], q[c]);
      differ_from_labels_only += p[0] != r[0] || p[1] != r[1] || p[2] != r[2];
    }
    QVERIFY(differ_from_labels_only > 0);
  }
};

int main(int argc, char** argv)
{
  meshpaint::studio::prepare_qt();
  QApplication app(argc, argv);
  app.setOrganizationName("meshpaint-test"); // recent files apart from a user's
  StudioTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "studio_test.moc"
