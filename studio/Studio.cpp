#include "Studio.h"

#include "PreferencesDialog.h"
#include "StudioWindow.h"

#include "core/errors.h" // for meshpaint::DeviceError

#include <QApplication>           // for QApplication
#include <QCoreApplication>       // for QCoreApplication::setOrganizationName
#include <QSurfaceFormat>         // for QSurfaceFormat
#include <QVTKOpenGLNativeWidget.h> // for QVTKOpenGLNativeWidget::defaultFormat

namespace meshpaint::studio {

DeviceChoice preferred_device()
{
  prepare_qt();
  const Preferences p = saved_preferences();
  return {p.device.toStdString(), p.storage.toStdString()};
}

void prepare_qt()
{
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  // The names QSettings files the preferences and recent files under, also before the application exists.
  if (QCoreApplication::organizationName().isEmpty())
    QCoreApplication::setOrganizationName("meshpaint");
  if (QCoreApplication::applicationName().isEmpty())
    QCoreApplication::setApplicationName("meshpaint");
}

int run_studio(vtkPaintView* view)
{
  prepare_qt();
  static int argc = 1;
  static char name[] = "meshpaint";
  static char* argv[] = {name, nullptr};
  QApplication app(argc, argv);
  QApplication::setApplicationName("meshpaint");
  QApplication::setOrganizationName("meshpaint");
  StudioWindow window(view);
  if (!window.ready())
    throw DeviceError(window.error().toStdString());
  window.show();
  return QApplication::exec();
}

} // namespace meshpaint::studio
