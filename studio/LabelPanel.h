// The studio's label classes: names and colours from the project (or
// labels.json) or added here; rename, recolour, hide, delete, and select a
// class to paint it with the label tool.
#pragma once

#include <QWidget> // for QWidget

class QTableWidget;
class vtkPaintView;

namespace meshpaint::studio {

class LabelPanel : public QWidget
{
public:
  explicit LabelPanel(vtkPaintView* view, QWidget* parent = nullptr);
  //! Lists the view's classes again.
  void sync();
  QTableWidget* table() { return table_; }
  //! Adds a class with the next free id and a palette colour; returns its id.
  int add_class();
  //! Paints class `id` from now on: the label tool, that id, labels shown.
  void paint_class(int id);

private:
  void recolour(int row);

  vtkPaintView* view_;
  QTableWidget* table_;
  bool syncing_ = false;
};

} // namespace meshpaint::studio
