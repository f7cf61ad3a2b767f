#include "LabelPanel.h"

#include "BrushSettings.h"  // for meshpaint::BrushSettings
#include "ChannelDisplay.h" // for meshpaint::label_colour
#include "vtkPaintView.h"   // for vtkPaintView

#include "paint/paint_scene.h"   // for meshpaint::PaintScene
#include "paint/paint_surface.h" // for meshpaint::PaintSurface
#include "project/label_stats.h" // for meshpaint::label_stats
#include "project/labels.h"      // for meshpaint::LabelClass

#include <QColorDialog>  // for QColorDialog
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
  table_ = new QTableWidget(0, 5);
  table_->setObjectName("label_classes");
  table_->setHorizontalHeaderLabels({"shown", "id", "name", "colour", "area"});
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

  connect(add, &QPushButton::clicked, [this] { paint_class(add_class()); });
  connect(recolour_button, &QPushButton::clicked, [this] { recolour(table_->currentRow()); });
  connect(remove, &QPushButton::clicked, [this] {
    const int row = table_->currentRow();
    if (row >= 0)
      view_->RemoveLabelClass(table_->item(row, kId)->text().toInt());
    sync();
  });
  connect(table_, &QTableWidget::cellClicked, [this](int row, int column) {
    if (column != kShown)
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
    } else if (item->column() == kName) { // rename
      for (const LabelClass& c : view_->GetLabelClasses())
        if (c.id == id)
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

void LabelPanel::sync()
{
  measure();
  syncing_ = true;
  const std::vector<LabelClass>& labels = view_->GetLabelClasses();
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
    table_->setItem(row, kName, new QTableWidgetItem(QString::fromStdString(c.name)));
    auto* colour = new QTableWidgetItem(qcolour(c.colour).name());
    colour->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    colour->setBackground(qcolour(c.colour));
    colour->setForeground(qcolour(c.colour).lightness() > 128 ? Qt::black : Qt::white);
    table_->setItem(row, kColour, colour);
    const auto area = areas_.find(c.id);
    auto* a = new QTableWidgetItem(QString::number(area == areas_.end() ? 0.0 : area->second, 'g', 4));
    a->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    table_->setItem(row, kArea, a);
  }
  if (selected >= 0 && selected < table_->rowCount())
    table_->selectRow(selected);
  syncing_ = false;
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
  const int id = table_->item(row, kId)->text().toInt();
  for (const LabelClass& c : view_->GetLabelClasses())
    if (c.id == id) {
      const QColor q = QColorDialog::getColor(qcolour(c.colour), this, "Colour of " + QString::fromStdString(c.name));
      if (q.isValid())
        view_->AddLabelClass(id, c.name.c_str(), q.redF(), q.greenF(), q.blueF());
      break;
    }
  sync();
}

} // namespace meshpaint::studio
