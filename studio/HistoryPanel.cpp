#include "HistoryPanel.h"

#include "vtkPaintView.h" // for vtkPaintView

#include "paint/paint_scene.h" // for meshpaint::PaintScene
#include "paint/stroke.h"      // for meshpaint::Stroke, tool_name

#include <QListWidget> // for QListWidget
#include <QVBoxLayout> // for QVBoxLayout

namespace meshpaint::studio {
namespace {

QString describe(const Stroke& s, std::size_t k)
{
  return QString("%1  %2, %3 points").arg(k + 1).arg(QString::fromStdString(tool_name(s.tool))).arg(s.points.size());
}

} // namespace

HistoryPanel::HistoryPanel(vtkPaintView* view, QWidget* parent) : QWidget(parent), view_(view)
{
  auto* layout = new QVBoxLayout(this);
  list_ = new QListWidget;
  list_->setObjectName("history");
  layout->addWidget(list_);
  // Row 0 is the surface before any stroke; row k, the surface after stroke k.
  connect(list_, &QListWidget::itemClicked, [this](QListWidgetItem* item) { go_to(list_->row(item)); });
  sync();
}

void HistoryPanel::sync()
{
  const PaintScene& scene = view_->GetScene();
  const std::vector<Stroke>& done = scene.history();
  const std::vector<Stroke>& undone = scene.undone();
  list_->clear();
  list_->addItem("0  (unpainted)");
  for (std::size_t k = 0; k < done.size(); ++k)
    list_->addItem(describe(done[k], k));
  for (std::size_t k = undone.size(); k-- > 0;) { // the next to redo first
    auto* item = new QListWidgetItem(describe(undone[k], done.size() + undone.size() - 1 - k) + "  (undone)");
    item->setForeground(Qt::gray);
    list_->addItem(item);
  }
  list_->setCurrentRow(int(done.size()));
}

void HistoryPanel::go_to(int strokes)
{
  while (int(view_->GetScene().history().size()) > strokes)
    if (!view_->Undo())
      break;
  while (int(view_->GetScene().history().size()) < strokes)
    if (!view_->Redo())
      break;
  sync();
}

} // namespace meshpaint::studio
