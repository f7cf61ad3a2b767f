#include "LabelPanel.h"
#include "ViewPixel.h"

#include "BrushSettings.h"  // for meshpaint::BrushSettings
#include "ChannelDisplay.h" // for meshpaint::label_colour, unnamed_label_class
#include "vtkPaintView.h"   // for vtkPaintView

#include "paint/paint_scene.h"   // for meshpaint::PaintScene
#include "paint/paint_surface.h" // for meshpaint::PaintSurface
#include "project/label_stats.h" // for meshpaint::label_stats
#include "project/labels.h"      // for meshpaint::LabelClass

#include "paint/stroke.h"        // for meshpaint::make_stroke, StrokeScript

#include <QCheckBox>     // for QCheckBox
#include <QColorDialog>  // for QColorDialog
#include <algorithm>     // for std::find, std::max, std::any_of, std::stable_sort
#include <QComboBox>     // for QComboBox
#include <QLabel>        // for QLabel
#include <QMouseEvent>   // for QMouseEvent
#include <QHBoxLayout>   // for QHBoxLayout
#include <QHeaderView>   // for QHeaderView
#include <QPushButton>   // for QPushButton
#include <QTableWidget>  // for QTableWidget
#include <QVBoxLayout>   // for QVBoxLayout

namespace meshpaint::studio {
namespace {

enum Column
{
  kShown,
  kLocked,
  kId,
  kName,
  kColour,
  kArea
};

QColor qcolour(const Vec3& c) { return QColor::fromRgbF(c[0], c[1], c[2]); }

} // namespace

LabelPanel::LabelPanel(vtkPaintView* view, QWidget* parent) : QWidget(parent), view_(view)
{
  auto* layout = new QVBoxLayout(this);
  table_ = new QTableWidget(0, 6);
  table_->setObjectName("label_classes");
  table_->setHorizontalHeaderLabels({"shown", "lock", "id", "name", "colour", "area"});
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setSectionResizeMode(kName, QHeaderView::Stretch);
  table_->verticalHeader()->hide();
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::SingleSelection);
  layout->addWidget(table_);
  auto* buttons = new QHBoxLayout;
  auto* add = new QPushButton("Add");
  auto* recolour_button = new QPushButton("Recolour...");
  auto* remove = new QPushButton("Delete");
  for (QPushButton* b : {add, recolour_button, remove})
    buttons->addWidget(b);
  layout->addLayout(buttons);
  // Label strokes paint over one class only, or over any but the locked.
  auto* over = new QHBoxLayout;
  over->addWidget(new QLabel("Paint only over"));
  only_over_ = new QComboBox;
  only_over_->setObjectName("only_over");
  over->addWidget(only_over_, 1);
  layout->addLayout(over);
  auto* tools = new QHBoxLayout;
  fill_ = new QPushButton("Fill");
  fill_->setObjectName("fill");
  fill_->setCheckable(true);
  fill_->setToolTip("A click on the surface fills the region of the class there with the chosen class (key g: under "
                    "the mouse)");
  diagonals_ = new QCheckBox("Diagonals");
  diagonals_->setObjectName("fill_diagonals");
  diagonals_->setToolTip("Fills connect texels that touch at a corner too, not only along a side (key G)");
  pick_ = new QPushButton("Pick");
  pick_->setObjectName("pick");
  pick_->setCheckable(true);
  pick_->setToolTip("Eyedropper: a click on the surface chooses the class there (key e: under the mouse)");
  merge_ = new QPushButton("Merge into");
  merge_->setObjectName("merge");
  merge_->setToolTip("The selected class's surface becomes the class chosen beside; the class is removed");
  merge_into_ = new QComboBox;
  merge_into_->setObjectName("merge_into");
  for (QWidget* w : {static_cast<QWidget*>(fill_), static_cast<QWidget*>(diagonals_), static_cast<QWidget*>(pick_),
                     static_cast<QWidget*>(merge_)})
    tools->addWidget(w);
  tools->addWidget(merge_into_, 1);
  layout->addLayout(tools);

  connect(only_over_, QOverload<int>::of(&QComboBox::activated), [this](int k) {
    if (BrushSettings* b = view_->GetBrush())
      b->set_only_over_label(only_over_->itemData(k).toInt());
    view_->UpdateText();
  });
  connect(diagonals_, &QCheckBox::toggled, [this](bool on) {
    BrushSettings* b = view_->GetBrush();
    if (syncing_ || !b)
      return;
    b->set_fill_diagonals(on);
    view_->UpdateText();
    view_->Render();
  });
  connect(fill_, &QPushButton::toggled, [this](bool on) {
    if (on)
      pick_->setChecked(false);
  });
  connect(pick_, &QPushButton::toggled, [this](bool on) {
    if (on)
      fill_->setChecked(false);
  });
  connect(merge_, &QPushButton::clicked, [this] {
    const int row = table_->currentRow();
    if (row >= 0 && merge_into_->currentIndex() >= 0)
      merge(table_->item(row, kId)->text().toInt(), merge_into_->currentData().toInt());
  });

  connect(add, &QPushButton::clicked, [this] { paint_class(add_class()); });
  connect(recolour_button, &QPushButton::clicked, [this] { recolour(table_->currentRow()); });
  connect(remove, &QPushButton::clicked, [this] {
    const int row = table_->currentRow();
    if (row >= 0)
      view_->RemoveLabelClass(table_->item(row, kId)->text().toInt());
    sync();
  });
  connect(table_, &QTableWidget::cellClicked, [this](int row, int column) {
    if (column != kShown && column != kLocked)
      paint_class(table_->item(row, kId)->text().toInt());
  });
  connect(table_, &QTableWidget::cellDoubleClicked, [this](int row, int column) {
    if (column == kColour)
      recolour(row);
  });
  connect(table_, &QTableWidget::itemChanged, [this](QTableWidgetItem* item) {
    if (syncing_)
      return;
    const int id = table_->item(item->row(), kId)->text().toInt();
    if (item->column() == kShown) {
      view_->SetLabelClassVisible(id, item->checkState() == Qt::Checked);
    } else if (item->column() == kLocked) {
      update_locks();
    } else if (item->column() == kName) { // rename (an id painted without a class becomes one)
      const LabelClass c = entry(id);
      view_->AddLabelClass(id, item->text().toStdString().c_str(), c.colour[0], c.colour[1], c.colour[2]);
      sync(); // a name taken or empty is refused: the old one comes back
    }
  });
  sync();
}

void LabelPanel::measure()
{
  PaintScene& scene = view_->GetScene();
  if (view_->IsPainting() || scene.empty())
    return;
  const std::tuple<const void*, std::size_t, std::size_t> now{&scene.surface(0), scene.history().size(),
                                                             scene.undone().size()};
  if (now == measured_)
    return;
  measured_ = now;
  areas_.clear();
  PaintSurface& surface = view_->GetScene().surface(0);
  for (const LabelStats& l : label_stats(surface.painted_surface(surface.level())))
    areas_[l.id] = l.area;
}

void LabelPanel::follow_merges()
{
  const PaintScene& scene = view_->GetScene();
  const std::vector<Stroke>& done = scene.history();
  const std::vector<Stroke>& undone = scene.undone(); // the next to redo last
  for (auto it = merged_.begin(); it != merged_.end();) {
    const std::size_t p = it->position;
    const Stroke* at = p < done.size() ? &done[p]
                       : p < done.size() + undone.size() ? &undone[done.size() + undone.size() - 1 - p]
                                                         : nullptr;
    const bool kept = at && at->tool == Tool::Merge && at->paint().only_over_label == it->entry.id;
    if (!kept) { // a new stroke after an undo dropped the merge for good
      it = merged_.erase(it);
      continue;
    }
    const bool applied = p < done.size();
    if (applied != it->applied) {
      // The view's change event comes back to sync(): state first, one change per call.
      it->applied = applied;
      const LabelClass c = it->entry;
      if (applied)
        view_->RemoveLabelClass(c.id);
      else
        view_->AddLabelClass(c.id, c.name.c_str(), c.colour[0], c.colour[1], c.colour[2]);
      return;
    }
    ++it;
  }
}

void LabelPanel::sync()
{
  follow_merges();
  measure();
  syncing_ = true;
  if (const BrushSettings* b = view_->GetBrush())
    diagonals_->setChecked(b->fill_diagonals());
  const std::vector<LabelClass> labels = listed();
  const int selected = table_->currentRow();
  table_->setRowCount(int(labels.size()));
  for (std::size_t k = 0; k < labels.size(); ++k) {
    const LabelClass& c = labels[k];
    const int row = int(k);
    auto* shown = new QTableWidgetItem;
    shown->setFlags(Qt::ItemIsUserCheckable | Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    shown->setCheckState(view_->GetLabelClassVisible(c.id) ? Qt::Checked : Qt::Unchecked);
    table_->setItem(row, kShown, shown);
    auto* id = new QTableWidgetItem(QString::number(c.id));
    id->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    table_->setItem(row, kId, id);
    auto* name = new QTableWidgetItem(QString::fromStdString(c.name));
    if (!named(c.id)) // painted without a class: a new name makes it one
      name->setToolTip("painted without a class: name it to keep it");
    table_->setItem(row, kName, name);
    auto* colour = new QTableWidgetItem(qcolour(c.colour).name());
    colour->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    colour->setBackground(qcolour(c.colour));
    colour->setForeground(qcolour(c.colour).lightness() > 128 ? Qt::black : Qt::white);
    table_->setItem(row, kColour, colour);
    const auto area = areas_.find(c.id);
    auto* a = new QTableWidgetItem(QString::number(area == areas_.end() ? 0.0 : area->second, 'g', 4));
    a->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    table_->setItem(row, kArea, a);
    auto* locked = new QTableWidgetItem;
    locked->setFlags(Qt::ItemIsUserCheckable | Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    const BrushSettings* b = view_->GetBrush();
    const bool is_locked = b && std::find(b->locked_labels().begin(), b->locked_labels().end(), c.id) != b->locked_labels().end();
    locked->setCheckState(is_locked ? Qt::Checked : Qt::Unchecked);
    table_->setItem(row, kLocked, locked);
  }
  sync_choices();
  if (selected >= 0 && selected < table_->rowCount())
    table_->selectRow(selected);
  syncing_ = false;
}

bool LabelPanel::named(int id) const
{
  const std::vector<LabelClass>& classes = view_->GetLabelClasses();
  return std::any_of(classes.begin(), classes.end(), [&](const LabelClass& c) { return c.id == id; });
}

LabelClass LabelPanel::entry(int id) const
{
  for (const LabelClass& c : view_->GetLabelClasses())
    if (c.id == id)
      return c;
  return unnamed_label_class(id);
}

std::vector<LabelClass> LabelPanel::listed() const
{
  std::vector<LabelClass> rows = view_->GetLabelClasses();
  for (const auto& [id, area] : areas_)
    if (id != 0 && !named(id))
      rows.push_back(unnamed_label_class(id));
  std::stable_sort(rows.begin(), rows.end(), [](const LabelClass& a, const LabelClass& b) { return a.id < b.id; });
  return rows;
}

int LabelPanel::add_class()
{
  int id = 1;
  std::vector<std::string> names;
  for (const LabelClass& c : view_->GetLabelClasses()) {
    id = std::max(id, c.id + 1);
    names.push_back(c.name);
  }
  std::string name = "class " + std::to_string(id);
  const std::array<double, 3> rgb = label_colour(id, {});
  view_->AddLabelClass(id, name.c_str(), rgb[0], rgb[1], rgb[2]);
  sync();
  return id;
}

void LabelPanel::paint_class(int id)
{
  if (BrushSettings* b = view_->GetBrush()) {
    b->set_tool("label");
    b->set_label(id);
  }
  if (std::string(view_->GetShownChannel()) != "label")
    view_->SetShownChannel("label");
  for (int row = 0; row < table_->rowCount(); ++row)
    if (table_->item(row, kId)->text().toInt() == id)
      table_->selectRow(row);
  view_->UpdateText();
  view_->Render();
}

void LabelPanel::recolour(int row)
{
  if (row < 0 || row >= table_->rowCount())
    return;
  const LabelClass c = entry(table_->item(row, kId)->text().toInt());
  const QColor q = QColorDialog::getColor(qcolour(c.colour), this, "Colour of " + QString::fromStdString(c.name));
  if (q.isValid())
    view_->AddLabelClass(c.id, c.name.c_str(), q.redF(), q.greenF(), q.blueF());
  sync();
}

} // namespace meshpaint::studio

namespace meshpaint::studio {

void LabelPanel::sync_choices()
{
  const BrushSettings* b = view_->GetBrush();
  const int over = b ? b->only_over_label() : -1, into = merge_into_->currentData().isValid() ? merge_into_->currentData().toInt() : -1;
  only_over_->clear();
  merge_into_->clear();
  only_over_->addItem("any class", -1);
  bool unlabelled = false;
  for (const LabelClass& c : listed()) {
    const QString text = QString("%1 %2").arg(c.id).arg(QString::fromStdString(c.name));
    only_over_->addItem(text, c.id);
    merge_into_->addItem(text, c.id);
    unlabelled = unlabelled || c.id == 0;
  }
  if (!unlabelled) // unlabelled surface counts as a class
    only_over_->insertItem(1, "0 unlabelled", 0);
  only_over_->setCurrentIndex(std::max(0, only_over_->findData(over)));
  if (merge_into_->findData(into) >= 0)
    merge_into_->setCurrentIndex(merge_into_->findData(into));
}

void LabelPanel::update_locks()
{
  BrushSettings* b = view_->GetBrush();
  if (!b)
    return;
  std::vector<int> ids;
  for (int row = 0; row < table_->rowCount(); ++row)
    if (table_->item(row, kLocked) && table_->item(row, kLocked)->checkState() == Qt::Checked)
      ids.push_back(table_->item(row, kId)->text().toInt());
  b->set_locked_labels(ids);
  view_->UpdateText();
}

bool LabelPanel::merge(int from, int into)
{
  const BrushSettings* b = view_->GetBrush();
  if (!b || from == into)
    return false;
  const std::vector<int>& locked = b->locked_labels();
  if (std::find(locked.begin(), locked.end(), from) != locked.end())
    return false; // a locked class keeps its surface, and so its entry
  StrokeScript script;
  Stroke s = make_stroke(Tool::Merge);
  s.paint().value[CHANNEL_LABEL] = {float(into), float(into), float(into), 1.f};
  s.paint().alpha[CHANNEL_LABEL] = 1.f;
  s.paint().only_over_label = from;
  s.paint().locked_labels = locked;
  script.strokes.push_back(s);
  const bool had_class = named(from);
  const LabelClass removed = entry(from);
  if (!view_->ApplyScript(script))
    return false;
  if (had_class) // an id without a class has no entry to bring back
    merged_.push_back({view_->GetScene().history().size() - 1, removed});
  view_->RemoveLabelClass(from);
  sync();
  paint_class(into);
  return true;
}

void LabelPanel::watch(QWidget* render)
{
  render_ = render;
  render->installEventFilter(this);
}

bool LabelPanel::eventFilter(QObject* watched, QEvent* event)
{
  const bool press = event->type() == QEvent::MouseButtonPress, release = event->type() == QEvent::MouseButtonRelease;
  if (watched != render_ || !(fill_->isChecked() || pick_->isChecked()) || !(press || release))
    return QWidget::eventFilter(watched, event);
  const auto* m = static_cast<QMouseEvent*>(event);
  if (m->button() != Qt::LeftButton)
    return QWidget::eventFilter(watched, event);
  if (press) {
    const QPoint at = view_pixel(render_, m);
    const int x = at.x(), y = at.y();
    if (fill_->isChecked()) {
      view_->FillAt(x, y);
    } else {
      if (BrushSettings* b = view_->GetBrush())
        b->set_tool("label");
      if (view_->PickAt(x, y))
        paint_class(view_->GetBrush()->label());
      pick_->setChecked(false);
    }
    sync();
  }
  return true; // the click was the panel's, not a stroke's or the camera's
}

} // namespace meshpaint::studio
