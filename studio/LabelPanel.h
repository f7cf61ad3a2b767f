// The studio's label classes: names and colours from the project (or
// labels.json) or added here; rename, recolour, hide, delete, and select a
// class to paint it with the label tool.
#pragma once

#include <QWidget> // for QWidget

#include <cstddef> // for std::size_t
#include <map>     // for std::map
#include <tuple>   // for std::tuple

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
  //! Each class's area on the surface now, measured again when strokes
  //! were added or undone since (not while a stroke is drawn).
  void measure();

  vtkPaintView* view_;
  QTableWidget* table_;
  bool syncing_ = false;
  std::map<int, double> areas_;            // class id to area, world units squared
  std::tuple<const void*, std::size_t, std::size_t> measured_{nullptr, 0, 0}; // surface, strokes done and undone then
};

} // namespace meshpaint::studio
