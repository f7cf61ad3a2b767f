// The studio's level panel: the painting level (a change rebuilds the
// surfaces at the new level off the interface thread and replays their
// strokes), the level geometry tools edit, the level of detail drawn while
// the camera moves.
#pragma once

#include <QWidget> // for QWidget

#include <functional> // for std::function

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;
class vtkPaintView;

namespace meshpaint::studio {

class LevelPanel : public QWidget
{
public:
  //! `change_level(L)` rebuilds the scene at painting level L (the window
  //! runs it in the background).
  LevelPanel(vtkPaintView* view, std::function<void(int)> change_level,
             QWidget* parent = nullptr);
  //! Shows the view's levels as they are now.
  void sync();
  //! Whether a level change may start now (not while other work runs).
  void set_busy(bool busy);
  QSpinBox* level() { return level_; }
  QPushButton* apply() { return apply_; }

private:
  //! The quads at the level chosen, and whether it can be applied.
  void show_level_choice();

  vtkPaintView* view_;
  std::function<void(int)> change_level_;
  bool syncing_ = false;
  bool busy_ = false;
  QSpinBox* level_;
  QPushButton* apply_;
  QLabel* quads_;
  QSpinBox* edit_level_;
  QComboBox* lod_;
  QDoubleSpinBox* rate_;
  QLabel* lod_in_use_;
};

} // namespace meshpaint::studio
