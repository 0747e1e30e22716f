#pragma once

#include <QObject>

class QLabel;
class QStatusBar;
class QTimer;

namespace fooball::gui {

class FrameRate;
class RunController;

/// The status bar's permanent fields: cursor position, runs, balls, simulated time, steps and
/// frames per second and the cost of a step per run, refreshed four times a second. It also
/// says how to give up a step that has run in the background for more than a second, warns
/// while any run has had steps cut short (cutShortNotice), and names the limits of its method
/// each run is beyond (crossedLimits), with what to do in the tooltip; checked at each refresh,
/// not per step.
class StatusPanel : public QObject {
  Q_OBJECT

 public:
  StatusPanel(QStatusBar& bar, const RunController& runs, const FrameRate& frameRate);

  void start();
  void update();
  /// Where the cursor is over the box (m).
  void showCursor(double x, double y);

 private:
  QLabel* addField(const QString& toolTip);
  void showCutShortSteps();
  void showCrossedLimits();

  QStatusBar& bar_;
  const RunController& runs_;
  const FrameRate& frameRate_;
  QTimer* timer_;
  QLabel* cursor_;
  QLabel* runsField_;
  QLabel* balls_;
  QLabel* time_;
  QLabel* steps_;
  QLabel* frames_;
  QLabel* stepCost_;
  QLabel* cutShort_;
  QLabel* limits_;
};

}  // namespace fooball::gui
