#pragma once

#include <QWidget>

class QLabel;
class QSlider;

namespace fooball::gui {

class RunController;

/// The rewind timeline in the status bar: a slider over the moments the runs can go back to
/// (fooball/run_history.h), usable while paused, and what the history holds, e.g. "history
/// 12.4 s, 0.6/256 MB" (its tooltip says what the numbers are). Dragging it rewinds every run
/// together (RunController:: rewindTo); continuing from there drops the future.
class TimelineBar : public QWidget {
  Q_OBJECT

 public:
  explicit TimelineBar(RunController& runs, QWidget* parent = nullptr);

  /// Follows the history: its moments, the one the runs are at, and whether they are paused.
  /// A timer calls it while running; the window after a rewind.
  void showHistory();

  QSlider* slider() const { return slider_; }
  QString text() const;

 private:
  RunController& runs_;
  QSlider* slider_;
  QLabel* text_;
  bool showing_ = false;  ///< set while showHistory() moves the slider: not the user's rewind
};

}  // namespace fooball::gui
