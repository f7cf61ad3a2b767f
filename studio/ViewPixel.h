// Where a mouse event on the view widget lies in VTK's display pixels, for
// the panels whose buttons make the next click on the surface theirs.
#pragma once

#include <QMouseEvent> // for QMouseEvent
#include <QWidget>     // for QWidget

namespace meshpaint::studio {

//! The event's position in `render`'s device pixels, origin bottom left (VTK's).
inline QPoint view_pixel(const QWidget* render, const QMouseEvent* event)
{
  const double scale = render->devicePixelRatioF();
  return {int(event->pos().x() * scale), int((render->height() - event->pos().y() - 1) * scale)};
}

} // namespace meshpaint::studio
