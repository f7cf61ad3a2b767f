#include "Studio.h"

#include "StudioWindow.h"

#include "core/errors.h" // for meshpaint::DeviceError

#include <QApplication>           // for QApplication
#include <QSurfaceFormat>         // for QSurfaceFormat
#include <QVTKOpenGLNativeWidget.h> // for QVTKOpenGLNativeWidget::defaultFormat

namespace meshpaint::studio {

void prepare_qt() { QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat()); }

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
