#pragma once

#include <QObject>
#include <QString>
#include <functional>

class QStatusBar;
class QWidget;

namespace fooball::gui {

/// How the app tells the user what happened: a line in the status bar (showStatus), or, for
/// what they must not miss, an error (a message box by default; tests record them instead).
/// A line longer than the room left of the status bar's fields is cut short with "…" rather
/// than painted over them, and the bar's tooltip has it whole while it shows.
class UserMessages : public QObject {
  Q_OBJECT

 public:
  using ErrorReporter = std::function<void(const QString& title, const QString& message)>;

  /// Shows lines in `bar` and message boxes over `window`; a child of `window`.
  UserMessages(QStatusBar& bar, QWidget& window);

  void setErrorReporter(ErrorReporter reporter) { reportError_ = std::move(reporter); }
  /// The line the status bar shows now, whole; empty once it has gone.
  QString status() const { return status_; }

 public slots:
  void showStatus(const QString& message);
  void reportError(const QString& title, const QString& message);

 private:
  QStatusBar& bar_;
  ErrorReporter reportError_;
  QString status_;
};

}  // namespace fooball::gui
