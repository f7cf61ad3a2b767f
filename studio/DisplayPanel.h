// The studio's display panel: what the view shows of the surface (the
// materials, the label classes in their colours with a legend, or one
// channel through a colour map with its colour bar) and the patch borders
// over it.
#pragma once

#include <QWidget> // for QWidget

#include <functional> // for std::function

class QCheckBox;
class QComboBox;
class vtkPaintView;

namespace meshpaint::studio {

class DisplayPanel : public QWidget
{
public:
  //! `show_borders(on)` shows the patch borders (the window keeps them
  //! with the View menu's entry).
  DisplayPanel(vtkPaintView* view, std::function<void(bool)> show_borders, QWidget* parent = nullptr);
  //! Shows the view's shown channel as it is now.
  void sync();
  QComboBox* shown() { return shown_; }
  QCheckBox* borders() { return borders_; }

private:
  vtkPaintView* view_;
  QComboBox* shown_;
  QCheckBox* borders_;
};

} // namespace meshpaint::studio
