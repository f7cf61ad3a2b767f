#include "DisplayPanel.h"

#include "ChannelDisplay.h" // for meshpaint::shown_channel_names
#include "vtkPaintView.h"

#include <QCheckBox>   // for QCheckBox
#include <QComboBox>   // for QComboBox
#include <QFormLayout> // for QFormLayout
#include <QLabel>      // for QLabel

#include <algorithm> // for std::find

namespace meshpaint::studio {

DisplayPanel::DisplayPanel(vtkPaintView* view, std::function<void(bool)> show_borders, QWidget* parent)
  : QWidget(parent), view_(view)
{
  auto* form = new QFormLayout(this);
  shown_ = new QComboBox;
  for (const std::string& name : shown_channel_names())
    shown_->addItem(QString::fromStdString(name));
  shown_->setObjectName("shown_channel");
  shown_->setToolTip("diffuse: the materials; label: the classes in their colours, with a legend; "
                     "specular, roughness, displacement, mask: through a colour map, with its colour bar (key v)");
  form->addRow("Shown", shown_);
  borders_ = new QCheckBox("Patch borders");
  borders_->setObjectName("patch_borders");
  borders_->setToolTip("Lines along the borders of the atlas's patches");
  form->addRow(borders_);
  connect(shown_, QOverload<int>::of(&QComboBox::activated),
          [this](int k) { view_->SetShownChannel(shown_channel_names()[std::size_t(k)].c_str()); });
  connect(borders_, &QCheckBox::toggled, [show_borders = std::move(show_borders)](bool on) { show_borders(on); });
  sync();
}

void DisplayPanel::sync()
{
  const std::vector<std::string>& names = shown_channel_names();
  const auto at = std::find(names.begin(), names.end(), std::string(view_->GetShownChannel()));
  const QSignalBlocker quiet(shown_);
  shown_->setCurrentIndex(at == names.end() ? 0 : int(at - names.begin()));
}

} // namespace meshpaint::studio
