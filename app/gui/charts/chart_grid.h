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

/// The charts shown, side by side and on top of each other: a wide, short dock under the box
/// fits them in a row, a tall one in a column.
class ChartGrid : public QWidget {
 public:
  explicit ChartGrid(QWidget* parent);

  /// Puts `shown` into the grid, in order, in as many columns as suit `area` (px); the first
  /// row carries the marker labels, each column's lowest chart the time axis' labels and title.
  void arrange(const std::vector<TimeChart*>& shown, QSize area);

 private:
  QGridLayout* layout_;
  int columns_ = 0;                 ///< as last arranged, to see when that changes
  std::vector<TimeChart*> charts_;  ///< the charts in the grid, in order
};

/// Lines up the plot areas of `shown`, so one time is at one x in every chart.
void alignPlotAreas(const std::vector<TimeChart*>& shown);

}  // namespace fooball::gui
