#include "widgets/user_messages.h"

#include <QMessageBox>
#include <QStatusBar>

namespace fooball::gui {

namespace {

constexpr int kStatusMessageMs = 8000;

}  // namespace

UserMessages::UserMessages(QStatusBar& bar, QWidget& window) : QObject(&window), bar_(bar) {
  reportError_ = [&window](const QString& title, const QString& message) {
    QMessageBox::warning(&window, title, message);
  };
}

void UserMessages::showStatus(const QString& message) {
  bar_.showMessage(message, kStatusMessageMs);
}

void UserMessages::reportError(const QString& title, const QString& message) {
  reportError_(title, message);
}

}  // namespace fooball::gui
