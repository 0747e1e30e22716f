#include "chart_grid.h"

#include <QGridLayout>
#include <algorithm>
#include <cmath>
#include <optional>

#include "time_chart.h"

namespace fooball::gui {

namespace {

/// px between charts in the grid.
constexpr int kChartSpacing = 2;
/// The shape a chart reads best in (width : height) and the narrowest it may get in a row of
/// several: below that its tick labels crowd out the curves.
constexpr double kChartAspect = 2.4;
constexpr int kMinChartWidth = 240;  // px

}  // namespace

int chartColumns(int charts, QSize area) {
  // The columns that give each chart the largest plot of its preferred shape; a tie goes to
  // fewer columns (wider charts).
  int best = 1;
  double bestHeight = -1.0;
  for (int columns = 1; columns <= std::max(charts, 1); ++columns) {
    const int rows = (charts + columns - 1) / columns;
    const double cellWidth = double(area.width()) / columns;
    if (columns > 1 && cellWidth < kMinChartWidth) break;
    const double cellHeight = double(area.height()) / std::max(rows, 1);
    const double height = std::min(cellWidth / kChartAspect, cellHeight);
    if (height > bestHeight + 0.5) {
      bestHeight = height;
      best = columns;
    }
  }
  return best;
}

int chartsThatFit(int charts, QSize area, int chartHeight) {
  // The most charts whose rows, at the columns chartColumns() gives them, are all tall enough.
  for (int count = charts; count > 1; --count) {
    const int columns = chartColumns(count, area);
    const int rows = (count + columns - 1) / columns;
    if (rows * chartHeight + (rows - 1) * kChartSpacing <= area.height()) return count;
  }
  return 1;
}

ChartGrid::ChartGrid(QWidget* parent) : QWidget(parent), layout_(new QGridLayout(this)) {
  layout_->setContentsMargins(0, 0, 0, 0);
  layout_->setSpacing(kChartSpacing);
}

void ChartGrid::arrange(const std::vector<TimeChart*>& shown, QSize area) {
  const int columns = chartColumns(int(shown.size()), area);
  if (columns == columns_ && shown == charts_) return;
  for (TimeChart* chart : charts_)
    layout_->removeWidget(chart);
  for (int row = 0; row < layout_->rowCount(); ++row)
    layout_->setRowStretch(row, 0);
  for (int column = 0; column < layout_->columnCount(); ++column)
    layout_->setColumnStretch(column, 0);
  columns_ = columns;
  charts_ = shown;
  for (std::size_t i = 0; i < shown.size(); ++i) {
    const int row = int(i) / columns;
    const int column = int(i) % columns;
    layout_->addWidget(shown[i], row, column);
    layout_->setRowStretch(row, 1);
    layout_->setColumnStretch(column, 1);
    shown[i]->setMarkerLabelsShown(row == 0);
    shown[i]->show();
  }
}

QSize ChartGrid::minimumSizeHint() const {
  QSize least;
  for (const TimeChart* chart : charts_)
    least = least.expandedTo(chart->minimumSizeHint().expandedTo(chart->minimumSize()));
  return least;
}

void alignPlotAreas(const std::vector<TimeChart*>& shown) {
  // Every shown chart's plot starts where the widest value labels need it to, and ends where the
  // bottom chart's last time label lets it.
  std::optional<PlotInsets> aligned;
  for (const TimeChart* chart : shown) {
    const std::optional<PlotInsets> natural = chart->naturalPlotInsets();
    if (!natural) continue;
    const PlotInsets widest = aligned.value_or(*natural);
    aligned =
        PlotInsets{std::max(widest.left, natural->left), std::max(widest.right, natural->right)};
  }
  if (!aligned) return;
  for (TimeChart* chart : shown) {
    const std::optional<PlotInsets> natural = chart->naturalPlotInsets();
    if (!natural) continue;
    const PlotInsets extra{aligned->left - natural->left, aligned->right - natural->right};
    const PlotInsets now = chart->extraMargins();
    // Half a pixel of tolerance, so rounding cannot start a relayout loop.
    if (std::abs(extra.left - now.left) >= 0.5 || std::abs(extra.right - now.right) >= 0.5)
      chart->setExtraMargins(extra);
  }
}

}  // namespace fooball::gui
