#include "LevelPanel.h"

#include "BrushSettings.h" // for meshpaint::BrushSettings
#include "vtkPaintView.h"  // for vtkPaintView

#include "atlas/patch_layout.h" // for meshpaint::kMaxLevel

#include <QComboBox>      // for QComboBox
#include <QDoubleSpinBox> // for QDoubleSpinBox
#include <QFormLayout>    // for QFormLayout
#include <QHBoxLayout>    // for QHBoxLayout
#include <QLabel>         // for QLabel
#include <QPushButton>    // for QPushButton
#include <QSpinBox>       // for QSpinBox

#include <QSignalBlocker> // for QSignalBlocker

#include <cmath> // for std::pow

namespace meshpaint::studio {

LevelPanel::LevelPanel(vtkPaintView* view, std::function<void(int)> change_level,
                       QWidget* parent)
  : QWidget(parent), view_(view), change_level_(std::move(change_level))
{
  auto* form = new QFormLayout(this);
  level_ = new QSpinBox;
  level_->setObjectName("level");
  level_->setRange(1, kMaxLevel);
  apply_ = new QPushButton("Change");
  apply_->setObjectName("apply_level");
  apply_->setToolTip("Subdivides the meshes again at this level and replays the strokes on them");
  auto* row = new QHBoxLayout;
  row->addWidget(level_, 1);
  row->addWidget(apply_);
  form->addRow("Painting level", row);
  quads_ = new QLabel;
  form->addRow(QString(), quads_);
  edit_level_ = new QSpinBox;
  edit_level_->setObjectName("edit_level");
  edit_level_->setToolTip("The level sculpt, smooth and the other geometry tools edit (keys l / L)");
  form->addRow("Edit level", edit_level_);
  lod_ = new QComboBox;
  lod_->setObjectName("lod");
  lod_->setToolTip("The level drawn while the camera moves or a stroke is drawn");
  form->addRow("Level of detail", lod_);
  rate_ = new QDoubleSpinBox;
  rate_->setObjectName("lod_rate");
  rate_->setRange(1, 120);
  rate_->setSuffix(" fps");
  rate_->setToolTip("The frame rate the automatic level of detail aims at");
  form->addRow("Aim at", rate_);
  lod_in_use_ = new QLabel;
  form->addRow("Drawn moving", lod_in_use_);

  connect(apply_, &QPushButton::clicked, [this] {
    if (!busy_ && level_->value() != view_->GetLevel())
      change_level_(level_->value());
  });
  connect(level_, QOverload<int>::of(&QSpinBox::valueChanged), [this](int) { show_level_choice(); });
  connect(edit_level_, QOverload<int>::of(&QSpinBox::valueChanged), [this](int level) {
    BrushSettings* b = view_->GetBrush();
    if (syncing_ || !b)
      return;
    b->set_edit_level(level);
    view_->UpdateText();
    view_->Render();
  });
  connect(lod_, QOverload<int>::of(&QComboBox::activated), [this](int k) {
    view_->SetLodLevel(k == 0 ? -1 : k == 1 ? 0 : k - 1); // automatic, off, level 1, 2, ...
    sync();
  });
  connect(rate_, QOverload<double>::of(&QDoubleSpinBox::valueChanged), [this](double fps) {
    if (!syncing_) {
      view_->SetLodFrameRate(fps);
      sync();
    }
  });
  sync();
}

void LevelPanel::set_busy(bool busy)
{
  busy_ = busy;
  sync();
}

void LevelPanel::show_level_choice()
{
  const int level = view_->GetLevel();
  const double quads = double(view_->GetFaceCount()) * std::pow(4.0, level_->value() - level);
  quads_->setText(QString("%L1 quads at level %2").arg(quads, 0, 'f', 0).arg(level_->value()));
  apply_->setEnabled(!busy_ && level_->value() != level);
}

void LevelPanel::sync()
{
  syncing_ = true;
  const int level = view_->GetLevel();
  if (!level_->hasFocus()) { // not while the user chooses one
    const QSignalBlocker quiet(level_);
    level_->setValue(level);
  }
  show_level_choice();
  edit_level_->setRange(1, level);
  if (const BrushSettings* b = view_->GetBrush())
    edit_level_->setValue(b->edit_level());
  lod_->clear();
  lod_->addItem("automatic");
  lod_->addItem("off");
  for (int k = 1; k < level; ++k)
    lod_->addItem(QString("level %1").arg(k));
  const int lod = view_->GetLodLevel();
  lod_->setCurrentIndex(lod < 0 ? 0 : lod == 0 || lod >= level ? 1 : lod + 1);
  rate_->setValue(view_->GetLodFrameRate());
  rate_->setEnabled(lod < 0);
  lod_in_use_->setText(QString("level %1").arg(view_->GetLodLevelInUse()));
  syncing_ = false;
}

} // namespace meshpaint::studio
