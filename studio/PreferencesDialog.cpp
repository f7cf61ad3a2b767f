#include "PreferencesDialog.h"

#include "vtkPaintView.h" // for vtkPaintView

#include "cl/runtime.h" // for meshpaint::Runtime

#include <QComboBox>        // for QComboBox
#include <QDialogButtonBox> // for QDialogButtonBox
#include <QFormLayout>      // for QFormLayout
#include <QLabel>           // for QLabel
#include <QSettings>        // for QSettings

#include <exception> // for std::exception

namespace meshpaint::studio {

Preferences saved_preferences()
{
  QSettings settings;
  return {settings.value("device").toString(), settings.value("storage").toString()};
}

void save_preferences(const Preferences& preferences)
{
  QSettings settings;
  settings.setValue("device", preferences.device);
  settings.setValue("storage", preferences.storage);
}

PreferencesDialog::PreferencesDialog(vtkPaintView* view, QWidget* parent) : QDialog(parent), view_(view)
{
  setWindowTitle("Preferences");
  auto* form = new QFormLayout(this);
  device_ = new QComboBox;
  device_->setObjectName("device");
  device_->addItem("default (the first GPU, else the first device)", QString());
  try {
    for (const DeviceInfo& d : Runtime::list_devices())
      device_->addItem(QString("%1:%2  %3").arg(d.platform_index).arg(d.device_index).arg(QString::fromStdString(d.name)),
                       QString("%1:%2").arg(d.platform_index).arg(d.device_index));
  } catch (const std::exception& e) { // no OpenCL platform: only the default to offer
    device_->setToolTip(e.what());
  }
  storage_ = new QComboBox;
  storage_->setObjectName("storage");
  storage_->addItem("the device's default", QString());
  storage_->addItem("buffer (fast on CPU devices)", QString("buffer"));
  storage_->addItem("image (GPUs that sample images in hardware)", QString("image"));
  const auto select = [](QComboBox* box, const QString& value) {
    const int k = box->findData(value);
    if (k >= 0)
      box->setCurrentIndex(k);
    else if (!value.isEmpty()) { // a selector typed on the command line ("cpu", part of a name)
      box->addItem(value, value);
      box->setCurrentIndex(box->count() - 1);
    }
  };
  select(device_, QString::fromStdString(view_->GetDevice()));
  select(storage_, QString::fromStdString(view_->GetStorage()));
  form->addRow("OpenCL device", device_);
  form->addRow("Atlas storage", storage_);
  form->addRow(new QLabel("Used for the surfaces opened from now on, and at the next start\n"
                          "(--device and --storage on the command line take precedence)."));
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  form->addRow(buttons);
  connect(buttons, &QDialogButtonBox::accepted, [this] {
    apply();
    accept();
  });
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
}

void PreferencesDialog::apply()
{
  const Preferences p{device_->currentData().toString(), storage_->currentData().toString()};
  save_preferences(p);
  view_->SetDevice(p.device.toStdString().c_str());
  view_->SetStorage(p.storage.toStdString().c_str());
}

} // namespace meshpaint::studio
