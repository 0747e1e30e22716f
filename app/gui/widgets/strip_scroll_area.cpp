#include "widgets/strip_scroll_area.h"

#include <QEvent>
#include <QScrollBar>

namespace fooball::gui {

StripScrollArea::StripScrollArea(QWidget* widget) {
  setWidget(widget);
  setWidgetResizable(true);
  setFrameShape(QFrame::NoFrame);
  setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded);
  setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
  setVisible(!widget->isHidden());
  widget->installEventFilter(this);
  fitHeight();
}

QSize StripScrollArea::minimumSizeHint() const {
  return {0, height()};
}

QSize StripScrollArea::sizeHint() const {
  return minimumSizeHint();
}

void StripScrollArea::fitHeight() {
  const bool scrolls = widget()->minimumSizeHint().width() > viewport()->width();
  setFixedHeight(widget()->sizeHint().height() +
                 (scrolls ? horizontalScrollBar()->sizeHint().height() : 0));
}

bool StripScrollArea::eventFilter(QObject* watched, QEvent* event) {
  if (watched == widget()) {
    switch (event->type()) {
      case QEvent::LayoutRequest:  // its rows changed
        fitHeight();
        break;
      case QEvent::ShowToParent:
        show();
        break;
      case QEvent::HideToParent:
        hide();
        break;
      default:
        break;
    }
  }
  return QScrollArea::eventFilter(watched, event);
}

void StripScrollArea::resizeEvent(QResizeEvent* event) {
  QScrollArea::resizeEvent(event);
  fitHeight();
}

}  // namespace fooball::gui
