#include "BrushPanel.h"
#include "ViewPixel.h"

#include "BrushSettings.h"  // for meshpaint::BrushSettings
#include "vtkPaintView.h"   // for vtkPaintView

#include <QButtonGroup>   // for QButtonGroup
#include <QCheckBox>      // for QCheckBox
#include <QColorDialog>   // for QColorDialog
#include <QComboBox>      // for QComboBox
#include <QDoubleSpinBox> // for QDoubleSpinBox
#include <QFormLayout>    // for QFormLayout
#include <QGridLayout>    // for QGridLayout
#include <QGroupBox>      // for QGroupBox
#include <QLabel>         // for QLabel
#include <QPainter>       // for QPainter
#include <QPainterPath>   // for QPainterPath
#include <QPixmap>        // for QPixmap
#include <QPushButton>    // for QPushButton
#include <QVBoxLayout>    // for QVBoxLayout

#include <vtkCamera.h>   // for vtkCamera
#include <vtkRenderer.h> // for vtkRenderer

#include <cmath> // for std::exp, std::tan

namespace meshpaint::studio {
namespace {

QComboBox* combo(const std::vector<std::string>& items)
{
  auto* box = new QComboBox;
  for (const std::string& s : items)
    box->addItem(QString::fromStdString(s));
  return box;
}

QColor qcolour(const std::array<double, 3>& rgb) { return QColor::fromRgbF(rgb[0], rgb[1], rgb[2]); }

//! The falloff's weight from the centre (t = 0) to the rim (t = 1), as the kernels weigh dabs.
double falloff_weight(const std::string& falloff, double t)
{
  if (falloff == "constant")
    return 1.0;
  if (falloff == "linear")
    return 1.0 - t;
  if (falloff == "gaussian")
    return std::exp(-4.5 * t * t);
  return 1.0 - t * t * (3.0 - 2.0 * t); // smoothstep
}

QPixmap falloff_picture(const std::string& falloff)
{
  QPixmap pixmap(120, 40);
  pixmap.fill(Qt::transparent);
  QPainter painter(&pixmap);
  painter.setRenderHint(QPainter::Antialiasing);
  QPainterPath path;
  for (int x = 0; x <= 120; ++x) {
    const double w = falloff_weight(falloff, std::abs(x - 60) / 60.0);
    const QPointF p(x, 38 - 36 * w);
    x == 0 ? path.moveTo(p) : path.lineTo(p);
  }
  painter.setPen(QPen(QColor(240, 200, 60), 2));
  painter.drawPath(path);
  return pixmap;
}

} // namespace

BrushPanel::BrushPanel(vtkPaintView* view, QWidget* parent) : QWidget(parent), view_(view)
{
  auto* layout = new QVBoxLayout(this);

  auto* tool_box = new QGroupBox("Tools");
  auto* tool_grid = new QGridLayout(tool_box);
  tools_ = new QButtonGroup(this);
  const std::vector<std::string>& tools = BrushSettings::tools();
  for (std::size_t k = 0; k < tools.size(); ++k) {
    auto* b = new QPushButton(QString::fromStdString(tools[k]));
    b->setCheckable(true);
    b->setObjectName(QString::fromStdString("tool_" + tools[k]));
    tools_->addButton(b, int(k));
    tool_grid->addWidget(b, int(k) / 3, int(k) % 3);
  }
  connect(tools_, &QButtonGroup::idClicked,
          [this](int k) { change([&](BrushSettings& b) { b.set_tool(BrushSettings::tools()[std::size_t(k)]); }); });
  layout->addWidget(tool_box);

  auto* brush_box = new QGroupBox("Brush");
  auto* form = new QFormLayout(brush_box);
  radius_ = new QDoubleSpinBox;
  radius_->setDecimals(5);
  radius_->setRange(1e-6, 1e6);
  radius_->setObjectName("radius");
  radius_pixels_ = new QLabel;
  form->addRow("Radius (world)", radius_);
  form->addRow("On screen", radius_pixels_);
  connect(radius_, QOverload<double>::of(&QDoubleSpinBox::valueChanged),
          [this](double r) { change([&](BrushSettings& b) { b.set_radius(r); }); });
  strength_ = new QDoubleSpinBox;
  strength_->setRange(0.0, 1.0);
  strength_->setSingleStep(0.1);
  form->addRow("Strength", strength_);
  connect(strength_, QOverload<double>::of(&QDoubleSpinBox::valueChanged),
          [this](double v) { change([&](BrushSettings& b) { b.set_strength(v); }); });
  falloff_ = combo(BrushSettings::falloffs());
  falloff_curve_ = new QLabel;
  form->addRow("Falloff", falloff_);
  form->addRow("", falloff_curve_);
  connect(falloff_, QOverload<int>::of(&QComboBox::activated), [this](int k) {
    change([&](BrushSettings& b) { b.set_falloff(BrushSettings::falloffs()[std::size_t(k)]); });
  });
  spacing_ = new QDoubleSpinBox;
  spacing_->setRange(0.01, 100.0);
  spacing_->setSingleStep(0.05);
  form->addRow("Spacing (x radius)", spacing_);
  connect(spacing_, QOverload<double>::of(&QDoubleSpinBox::valueChanged),
          [this](double v) { change([&](BrushSettings& b) { b.set_spacing(v); }); });
  space_ = combo(BrushSettings::spaces());
  form->addRow("Space", space_);
  connect(space_, QOverload<int>::of(&QComboBox::activated), [this](int k) {
    change([&](BrushSettings& b) { b.set_space(BrushSettings::spaces()[std::size_t(k)]); });
  });
  mirror_ = combo({"off", "x", "y", "z"});
  form->addRow("Mirror", mirror_);
  connect(mirror_, QOverload<int>::of(&QComboBox::activated),
          [this](int k) { change([&](BrushSettings& b) { b.set_mirror(k - 1); }); });
  backfaces_ = new QCheckBox("paint faces turned away");
  form->addRow("Back faces", backfaces_);
  connect(backfaces_, &QCheckBox::toggled, [this](bool on) { change([&](BrushSettings& b) { b.set_backfaces(on); }); });
  op_ = combo(BrushSettings::ops());
  form->addRow("Op", op_);
  connect(op_, QOverload<int>::of(&QComboBox::activated),
          [this](int k) { change([&](BrushSettings& b) { b.set_op(BrushSettings::ops()[std::size_t(k)]); }); });
  layout->addWidget(brush_box);

  auto* colour_box = new QGroupBox("Colour");
  auto* colour_grid = new QGridLayout(colour_box);
  colour_ = new QPushButton("Pick...");
  colour_->setObjectName("colour");
  connect(colour_, &QPushButton::clicked, [this] {
    const BrushSettings* b = view_->GetBrush();
    const QColor c = QColorDialog::getColor(b ? qcolour(b->colour()) : Qt::red, this, "Brush colour");
    if (c.isValid())
      set_colour(c);
  });
  colour_grid->addWidget(colour_, 0, 0, 1, 4);
  eyedropper_ = new QPushButton("Eyedropper");
  eyedropper_->setObjectName("eyedropper");
  eyedropper_->setCheckable(true);
  eyedropper_->setToolTip("A click on the surface takes the diffuse colour there into the brush (key e: under the "
                          "mouse)");
  colour_grid->addWidget(eyedropper_, 0, 4);
  for (int k = 0; k < 10; ++k) {
    auto* swatch = new QPushButton(QString::number(k));
    swatch->setObjectName(QString("swatch_%1").arg(k));
    const QColor c = qcolour(BrushSettings::swatch_colour(k));
    swatch->setStyleSheet(QString("background-color: %1; color: %2").arg(c.name(), c.lightness() > 128 ? "black" : "white"));
    connect(swatch, &QPushButton::clicked, [this, k] { change([&](BrushSettings& b) { b.set_swatch(k); }); });
    colour_grid->addWidget(swatch, 1 + k / 5, k % 5);
  }
  layout->addWidget(colour_box);

  auto* channel_box = new QGroupBox("Channels");
  auto* channel_form = new QFormLayout(channel_box);
  channel_ = combo(BrushSettings::channels());
  channel_->setObjectName("painted_channel");
  channel_form->addRow("Painted", channel_);
  connect(channel_, QOverload<int>::of(&QComboBox::activated), [this](int k) {
    change([&](BrushSettings& b) { b.set_channel(BrushSettings::channels()[std::size_t(k)]); });
  });
  layout->addWidget(channel_box);
  layout->addStretch();
  sync();
}

void BrushPanel::watch(QWidget* render)
{
  render_ = render;
  render->installEventFilter(this);
}

bool BrushPanel::eventFilter(QObject* watched, QEvent* event)
{
  const bool press = event->type() == QEvent::MouseButtonPress, release = event->type() == QEvent::MouseButtonRelease;
  if (watched != render_ || !eyedropper_->isChecked() || !(press || release) ||
      static_cast<QMouseEvent*>(event)->button() != Qt::LeftButton)
    return QWidget::eventFilter(watched, event);
  if (press) {
    // The colour, not a class: the label tool's eyedropper is the label panel's Pick.
    if (BrushSettings* b = view_->GetBrush(); b && b->tool() == "label")
      b->set_tool("paint");
    const QPoint at = view_pixel(render_, static_cast<QMouseEvent*>(event));
    view_->PickAt(at.x(), at.y());
    eyedropper_->setChecked(false);
    view_->UpdateText();
    view_->Render();
  }
  return true; // the click was the eyedropper's, not a stroke's or the camera's
}

template <typename F>
void BrushPanel::change(F&& change)
{
  BrushSettings* b = view_->GetBrush();
  if (syncing_ || !b)
    return;
  change(*b);
  view_->UpdateText(); // shows the change, and tells the panels
  view_->Render();
}

void BrushPanel::set_colour(const QColor& c)
{
  change([&](BrushSettings& b) { b.set_colour({c.redF(), c.greenF(), c.blueF()}); });
}

void BrushPanel::sync()
{
  const BrushSettings* b = view_->GetBrush();
  if (!b)
    return;
  syncing_ = true;
  const auto index = [](const std::vector<std::string>& list, const std::string& s) {
    for (std::size_t k = 0; k < list.size(); ++k)
      if (list[k] == s)
        return int(k);
    return 0;
  };
  if (QAbstractButton* t = tools_->button(index(BrushSettings::tools(), b->tool())))
    t->setChecked(true);
  radius_->setValue(b->radius());
  // The radius on screen: at the focal point's depth, from the camera's view angle.
  if (vtkRenderer* r = view_->GetRenderer()) {
    vtkCamera* c = r->GetActiveCamera();
    const int* size = r->GetSize();
    const double half_height = c->GetDistance() * std::tan(0.5 * c->GetViewAngle() * M_PI / 180.0);
    radius_pixels_->setText(size[1] > 0 && half_height > 0
                              ? QString("%1 pixels").arg(b->radius() / half_height * 0.5 * size[1], 0, 'f', 0)
                              : QString("-"));
  }
  strength_->setValue(b->strength());
  falloff_->setCurrentIndex(index(BrushSettings::falloffs(), b->falloff()));
  falloff_curve_->setPixmap(falloff_picture(b->falloff()));
  spacing_->setValue(b->spacing());
  space_->setCurrentIndex(index(BrushSettings::spaces(), b->space()));
  mirror_->setCurrentIndex(b->mirror() + 1);
  backfaces_->setChecked(b->backfaces());
  op_->setCurrentIndex(index(BrushSettings::ops(), b->op()));
  const QColor c = qcolour(b->colour());
  colour_->setStyleSheet(QString("background-color: %1; color: %2").arg(c.name(), c.lightness() > 128 ? "black" : "white"));
  channel_->setCurrentIndex(index(BrushSettings::channels(), b->channel()));
  syncing_ = false;
}

} // namespace meshpaint::studio
