#pragma once

#include <QObject>

class QLabel;
class QStatusBar;
class QTimer;

namespace fooball::gui {

class FrameRate;
class RunController;

/// The status bar's permanent fields: cursor position, balls and simulated time, steps and
/// frames per second and the cost of a step (the slowest run's), refreshed four times a second,
/// each short enough that eight runs at 1000 px leave the timeline its room; tooltips wrap. It also
/// says how to give up a step that has run in the background for more than a second, warns
/// while any run has had steps cut short (cutShortNotice), points out an energy error a user
/// would care about (kNoticeableEnergyError), and names the limits of its method
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
  /// Runs whose relative energy error passed kNoticeableEnergyError (fooball/limit_check.h),
  /// each with the option that lowers it where its backend has one.
  void showEnergyErrors();
  /// How a notice names run `index`: its spec, or in compare mode "run 2".
  QString runName(int index) const;

  QStatusBar& bar_;
  const RunController& runs_;
  const FrameRate& frameRate_;
  QTimer* timer_;
  QLabel* cursor_;
  QLabel* ballsAndTime_;
  QLabel* rates_;
  QLabel* stepCost_;
  QLabel* cutShort_;
  QLabel* energy_;
  QLabel* limits_;
};

}  // namespace fooball::gui
