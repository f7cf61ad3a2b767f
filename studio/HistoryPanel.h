// The studio's undo history: the strokes applied, then those undone (which
// redo puts back); clicking an entry undoes or redoes up to it.
#pragma once

#include <QWidget> // for QWidget

class QListWidget;
class vtkPaintView;

namespace meshpaint::studio {

class HistoryPanel : public QWidget
{
public:
  explicit HistoryPanel(vtkPaintView* view, QWidget* parent = nullptr);
  //! Lists the view's strokes again.
  void sync();
  QListWidget* list() { return list_; }
  //! Undoes or redoes until `strokes` strokes are applied (0: none).
  void go_to(int strokes);

private:
  vtkPaintView* view_;
  QListWidget* list_;
};

} // namespace meshpaint::studio
