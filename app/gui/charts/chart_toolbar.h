#pragma once

#include <QWidget>

class QAction;
class QDoubleSpinBox;
class QHBoxLayout;

namespace fooball::gui {

/// The chart panel's switches: the time axis (the whole run, or a scrolling window of so many
/// seconds) and, per chart, which quantities it draws. Each switch is a check box beside its
/// name; the panel reads them (shown()) when one changes. The groups of switches wrap into rows
/// in a narrow panel (the charts' column at 1000 px holds three), none hidden behind a "»".
class ChartToolBar : public QWidget {
  Q_OBJECT

 public:
  /// Which quantities the switches show.
  struct Shown {
    bool momentumX = true;
    bool momentumY = true;
    bool momentumMagnitude = true;
    bool kinetic = true;
    bool potential = true;
    bool total = true;
    bool residual = true;
    bool relativeResidual = false;  ///< the residual divided by |E₀| instead of in joules
    bool divergence = true;
  };

  explicit ChartToolBar(QWidget* parent = nullptr);

  Shown shown() const;
  bool wholeRun() const;
  /// s of simulated time the scrolling window spans.
  double windowSeconds() const;
  /// These set the switches without signalling.
  void setWholeRun(bool whole);
  /// Whole seconds from 1 s to 1 h (clamped).
  void setWindowSeconds(double seconds);

 signals:
  void wholeRunToggled(bool whole);
  void windowSecondsChanged(double seconds);
  /// A quantity was switched on or off.
  void shownChanged();

 private:
  /// A group of switches kept on one row: the flow wraps between groups, not inside one.
  QHBoxLayout* addGroup();
  /// A check box switch beside its name, as a tool button in `group`.
  QAction* addToggle(QHBoxLayout& group, const QString& text, const QString& toolTip,
                     const QString& objectName);
  QAction* addQuantityToggle(QHBoxLayout& group, const QString& text, const QString& toolTip,
                             const QString& objectName);

  QAction* wholeRun_ = nullptr;
  QDoubleSpinBox* windowSpin_ = nullptr;  ///< s, the scrolling window's length
  QAction* momentumX_ = nullptr;
  QAction* momentumY_ = nullptr;
  QAction* momentumMagnitude_ = nullptr;
  QAction* kinetic_ = nullptr;
  QAction* potential_ = nullptr;
  QAction* total_ = nullptr;
  QAction* residual_ = nullptr;
  QAction* relativeResidual_ = nullptr;
  QAction* divergence_ = nullptr;
};

}  // namespace fooball::gui
