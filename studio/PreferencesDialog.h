// The studio's preferences: the OpenCL device and the atlas storage
// (buffer or image) surfaces are made on, as the command line's --device and
// --storage, kept with QSettings for the next start.
#pragma once

#include <QDialog> // for QDialog
#include <QString> // for QString

class QComboBox;
class vtkPaintView;

namespace meshpaint::studio {

//! What the preferences keep; empty: the device's (or the platform's) default.
struct Preferences
{
  QString device;  //!< a device selector as `meshpaint devices` lists ("0:1", "cpu", part of a name)
  QString storage; //!< "buffer", "image" or empty
};

//! The preferences saved (QSettings "device", "storage").
Preferences saved_preferences();
void save_preferences(const Preferences& preferences);

class PreferencesDialog : public QDialog
{
public:
  //! Shows the view's device and storage; OK saves them and sets them on
  //! the view, for the surfaces made from then on (opening a mesh, a level
  //! change).
  explicit PreferencesDialog(vtkPaintView* view, QWidget* parent = nullptr);
  QComboBox* device() { return device_; }
  QComboBox* storage() { return storage_; }
  //! Saves the choice and sets it on the view (what OK does).
  void apply();

private:
  vtkPaintView* view_;
  QComboBox* device_;
  QComboBox* storage_;
};

} // namespace meshpaint::studio
