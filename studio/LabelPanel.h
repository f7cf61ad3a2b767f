// The studio's label classes: names and colours from the project (or
// labels.json) or added here; rename, recolour, hide, lock, delete, merge,
// select a class to paint it with the label tool, paint only over one
// class, fill a region and pick a class off the surface.
#pragma once

#include "project/labels.h" // for meshpaint::LabelClass

#include <QWidget> // for QWidget

#include <cstddef> // for std::size_t
#include <map>     // for std::map
#include <tuple>   // for std::tuple
#include <vector>  // for std::vector

class QCheckBox;
class QComboBox;
class QPushButton;
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
  //! Clicks on `render` fill or pick while the Fill or Pick button is down.
  void watch(QWidget* render);
  //! Merges class `from` into class `into` (one stroke, "tool": "merge")
  //! and removes class `from`; false when `from` is locked or the merge fails.
  bool merge(int from, int into);
  QComboBox* only_over() { return only_over_; }
  QComboBox* merge_into() { return merge_into_; }
  QPushButton* fill_button() { return fill_; }
  QCheckBox* fill_diagonals() { return diagonals_; }
  QPushButton* pick_button() { return pick_; }
  QPushButton* merge_button() { return merge_; }

protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

private:
  //! The rows: the view's classes and, as unnamed_label_class(), each id
  //! painted without one (naming or recolouring it makes it a class).
  std::vector<LabelClass> listed() const;
  bool named(int id) const;
  //! Class `id`, or its unnamed entry.
  LabelClass entry(int id) const;
  //! The brush's locked classes from the table's lock column.
  void update_locks();
  //! The combo boxes' lists of classes, their choice kept.
  void sync_choices();
  void recolour(int row);
  //! Each class's area on the surface now, measured again when strokes
  //! were added or undone since (not while a stroke is drawn).
  void measure();

  //! A class a merge took out of the table: an undo past the merge puts its
  //! entry back (its texels come back with it), a redo takes it out again.
  struct MergedAway
  {
    std::size_t position;     //!< the merge's index in the history
    LabelClass entry;
    bool applied = true;      //!< the merge done, as of the last sync
  };
  void follow_merges();

  std::vector<MergedAway> merged_;
  vtkPaintView* view_;
  QTableWidget* table_;
  QComboBox* only_over_;  // any class, or one class (unlabelled among them)
  QComboBox* merge_into_; // the class the selected one merges into
  QPushButton *fill_, *pick_, *merge_;
  QCheckBox* diagonals_; // fills connect across corners too
  QWidget* render_ = nullptr;
  bool syncing_ = false;
  std::map<int, double> areas_;            // class id to area, world units squared
  std::tuple<const void*, std::size_t, std::size_t> measured_{nullptr, 0, 0}; // surface, strokes done and undone then
};

} // namespace meshpaint::studio
