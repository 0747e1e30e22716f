#include "widgets/user_messages.h"

#include <QMessageBox>
#include <QStatusBar>
#include <algorithm>

namespace fooball::gui {

namespace {

constexpr int kStatusMessageMs = 8000;
constexpr int kMessageMargin = 12;  // px: QStatusBar's own indent and the gap to the first field

}  // namespace

UserMessages::UserMessages(QStatusBar& bar, QWidget& window) : QObject(&window), bar_(bar) {
  reportError_ = [&window](const QString& title, const QString& message) {
    QMessageBox::warning(&window, title, message);
  };
  connect(&bar, &QStatusBar::messageChanged, this, [this](const QString& shown) {
    if (!shown.isEmpty()) return;
    status_.clear();
    bar_.setToolTip(QString());
  });
}

void UserMessages::showStatus(const QString& message) {
  status_ = message;
  bar_.showMessage(message, kStatusMessageMs);  // hides the bar's normal widgets
  // The bar paints the line from its left edge up to its first field, not clipped: it must fit.
  int room = bar_.width();
  for (const QWidget* field : bar_.findChildren<QWidget*>(Qt::FindDirectChildrenOnly)) {
    if (field->isVisible()) room = std::min(room, field->x());
  }
  room -= kMessageMargin;
  const QString fitted = bar_.fontMetrics().elidedText(message, Qt::ElideRight, room);
  bar_.setToolTip(fitted == message ? QString() : message);
  if (fitted != message) bar_.showMessage(fitted, kStatusMessageMs);
  status_ = message;
}

void UserMessages::reportError(const QString& title, const QString& message) {
  reportError_(title, message);
}

}  // namespace fooball::gui
