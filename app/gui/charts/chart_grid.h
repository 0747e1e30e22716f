#pragma once

#include <QSize>
#include <QWidget>
#include <vector>

class QGridLayout;

namespace fooball::gui {

class TimeChart;

/// How many columns `charts` charts get in `area` (px): each as large as it can be at about
/// 2.4 : 1, none narrower than 240 px beside another.
int chartColumns(int charts, QSize area);

/// How many of `charts` charts, each at least `chartHeight` px tall (a readable plot with its
/// title, legend and time axis), fit whole in `area` (px): at least one.
int chartsThatFit(int charts, QSize area, int chartHeight);

/// The charts shown, side by side and on top of each other: a wide, short dock fits them in a
/// row, a tall one in a column. Every chart placed is whole, with its own time axis; ChartPanel
/// hides those that do not fit and offers a selector for them.
class ChartGrid : public QWidget {
 public:
  explicit ChartGrid(QWidget* parent);

  /// Puts `shown` into the grid, in order, in as many columns as suit `area` (px); the first row
  /// carries the marker labels.
  void arrange(const std::vector<TimeChart*>& shown, QSize area);
  /// One chart's: the panel shows fewer charts when it gets less room, so the charts in the grid
  /// now must not hold the window at their size.
  QSize minimumSizeHint() const override;

 private:
  QGridLayout* layout_;
  int columns_ = 0;                 ///< as last arranged, to see when that changes
  std::vector<TimeChart*> charts_;  ///< the charts in the grid, in order
};

/// Lines up the plot areas of `shown`, so one time is at one x in every chart.
void alignPlotAreas(const std::vector<TimeChart*>& shown);

}  // namespace fooball::gui
