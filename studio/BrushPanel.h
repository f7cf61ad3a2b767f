// The studio's brush panel: the tool, the brush's settings, its colour (a
// picker and the swatches) and the channel painted. Every change
// goes to the view's BrushSettings, the same the keys change.
#pragma once

#include <QWidget> // for QWidget

class QButtonGroup;
class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class vtkPaintView;

namespace meshpaint::studio {

class BrushPanel : public QWidget
{
public:
  explicit BrushPanel(vtkPaintView* view, QWidget* parent = nullptr);
  //! Shows the view's brush as it is now (after a key changed it).
  void sync();
  //! Picks a colour for the colour channels (the picker's dialog sets it so).
  void set_colour(const QColor& colour);
  //! Clicks on `render` pick the colour there while the Eyedropper button is down.
  void watch(QWidget* render);
  QPushButton* eyedropper() { return eyedropper_; }

protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

private:
  //! Applies `change` to the brush, then shows the view's new state.
  template <typename F>
  void change(F&& change);

  vtkPaintView* view_;
  bool syncing_ = false;
  QButtonGroup* tools_;
  QDoubleSpinBox* radius_;
  QLabel* radius_pixels_;
  QDoubleSpinBox* strength_;
  QComboBox* falloff_;
  QLabel* falloff_curve_;
  QDoubleSpinBox* spacing_;
  QComboBox* space_;
  QComboBox* mirror_;
  QCheckBox* backfaces_;
  QComboBox* op_;
  QPushButton* colour_;
  QPushButton* eyedropper_;
  QWidget* render_ = nullptr;
  QComboBox* channel_;
};

} // namespace meshpaint::studio
