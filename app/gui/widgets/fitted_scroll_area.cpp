#include "widgets/fitted_scroll_area.h"

#include <QEvent>
#include <QScrollBar>

namespace fooball::gui {

FittedScrollArea::FittedScrollArea(QWidget* widget) {
  setWidget(widget);
  setWidgetResizable(true);
  setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  fitWidth();
  widget->installEventFilter(this);
}

void FittedScrollArea::fitWidth() {
  setMinimumWidth(widget()->minimumSizeHint().width() + verticalScrollBar()->sizeHint().width() +
                  2 * frameWidth());
}

bool FittedScrollArea::eventFilter(QObject* watched, QEvent* event) {
  // The widget's rows change, laid out in a posted event.
  if (watched == widget() && event->type() == QEvent::LayoutRequest) fitWidth();
  return QScrollArea::eventFilter(watched, event);
}

}  // namespace fooball::gui
