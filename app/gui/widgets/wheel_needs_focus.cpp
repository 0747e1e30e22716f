#include "widgets/wheel_needs_focus.h"

#include <QAbstractScrollArea>
#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QWheelEvent>

namespace fooball::gui {

namespace {

bool takesTheWheel(const QObject* object) {
  return qobject_cast<const QAbstractSlider*>(object) ||
         qobject_cast<const QAbstractSpinBox*>(object) || qobject_cast<const QComboBox*>(object);
}

}  // namespace

WheelNeedsFocus::WheelNeedsFocus(QAbstractScrollArea& area) : QObject(&area), area_(area) {
  qApp->installEventFilter(this);
}

bool WheelNeedsFocus::eventFilter(QObject* watched, QEvent* event) {
  const QEvent::Type type = event->type();
  if ((type != QEvent::Polish && type != QEvent::Wheel) || !takesTheWheel(watched)) return false;
  auto* control = static_cast<QWidget*>(watched);
  // The area's own scroll bar scrolls as always.
  if (!area_.viewport()->isAncestorOf(control)) return false;
  if (type == QEvent::Polish) {
    // Qt::WheelFocus (spin and combo boxes) would focus the control at the first notch.
    if (control->focusPolicy() == Qt::WheelFocus) control->setFocusPolicy(Qt::StrongFocus);
    return false;
  }
  if (control->hasFocus()) return false;
  const auto* wheel = static_cast<QWheelEvent*>(event);
  QWidget* viewport = area_.viewport();
  const QPointF position = viewport->mapFromGlobal(wheel->globalPosition());
  QWheelEvent forwarded(position, wheel->globalPosition(), wheel->pixelDelta(), wheel->angleDelta(),
                        wheel->buttons(), wheel->modifiers(), wheel->phase(), wheel->inverted(),
                        Qt::MouseEventSynthesizedByApplication, wheel->pointingDevice());
  QCoreApplication::sendEvent(viewport, &forwarded);
  event->accept();  // a spontaneous wheel would go on to the area's viewport a second time
  return true;
}

}  // namespace fooball::gui
