#include "chart_style.h"

#include <QChart>
#include <QFont>
#include <QGraphicsLayout>
#include <QLegend>
#include <QList>
#include <QValueAxis>

#include "run_palette.h"

namespace fooball::gui {
namespace {

/// How a quantity is drawn: its one-run colour, and its rank in its chart (0 for the headline
/// quantity — |p|, total energy, the residual — then 1 and 2 for its parts).
struct QuantityLook {
  QColor singleRunColour;
  int rank;
};

QuantityLook lookOf(Quantity quantity) {
  switch (quantity) {
    case Quantity::MomentumX:
      return {QColor(0x4f, 0xc3, 0xf7), 1};
    case Quantity::MomentumY:
      return {QColor(0xf0, 0x62, 0x92), 2};
    case Quantity::MomentumMagnitude:
      return {QColor(0xff, 0xd5, 0x4f), 0};
    case Quantity::KineticEnergy:
      return {QColor(0xff, 0x8a, 0x65), 1};
    case Quantity::PotentialEnergy:
      return {QColor(0x64, 0xb5, 0xf6), 2};
    case Quantity::TotalEnergy:
      return {QColor(0xf5, 0xf5, 0xf5), 0};
    case Quantity::EnergyResidual:
    case Quantity::RelativeEnergyResidual:
      return {QColor(0x81, 0xc7, 0x84), 0};
    case Quantity::RmsPositionDifference:
      return {QColor(0xce, 0x93, 0xd8), 0};
    case Quantity::MaxPositionDifference:
      return {QColor(0xce, 0x93, 0xd8), 1};
  }
  return {Qt::white, 0};
}

}  // namespace

QPen baselinePen() {
  // As heavy as a run's headline curve, so it can be followed at a glance; the dashes say it is
  // a reference, not a method.
  QPen pen(colours::neutralColour(), 2.0);
  pen.setDashPattern({4.0, 3.0});
  return pen;
}

QPen curvePen(Quantity quantity, int runIndex, bool colourByRun) {
  const QuantityLook look = lookOf(quantity);
  const QColor colour = colourByRun ? colours::runColour(runIndex) : look.singleRunColour;
  // The headline curve is heavier, so the eye finds it first.
  if (look.rank == 0) return QPen(colour, 2.0);
  // The parts are one pixel wide: Qt draws such lines directly, where a wider pen is stroked
  // into an outline first, which over thousands of points costs milliseconds a frame. Not
  // cosmetic, so an export at twice the pixels draws them twice as wide, like everything else.
  QPen pen(colour, 1.0);
  // In compare mode the colour says the run, so the line style says the part: dashed for the
  // first, dotted for the second (patterns in pen widths).
  if (colourByRun) {
    pen.setDashPattern(look.rank == 1 ? QList<qreal>{6.0, 3.0} : QList<qreal>{1.5, 2.5});
  }
  return pen;
}

QFont sizedFont(const QFont& base, double pointSize, bool bold) {
  QFont font = base;
  font.setPointSizeF(pointSize);
  font.setBold(bold);
  return font;
}

void styleChart(QChart* chart, const QString& title, const QFont& baseFont) {
  // The theme first: it restyles everything already in the chart.
  chart->setTheme(QChart::ChartThemeDark);
  chart->setAnimationOptions(QChart::NoAnimation);
  chart->setBackgroundBrush(chart_colours::kBackground);
  chart->setBackgroundRoundness(0.0);
  chart->setPlotAreaBackgroundBrush(chart_colours::kPlotArea);
  chart->setPlotAreaBackgroundVisible(true);
  chart->layout()->setContentsMargins(0, 0, 0, 0);
  chart->setTitle(title);
  chart->setTitleFont(sizedFont(baseFont, 9.0, true));
  chart->setTitleBrush(chart_colours::kTitle);

  QLegend* legend = chart->legend();
  legend->setAlignment(Qt::AlignTop);
  legend->setFont(sizedFont(baseFont, 8.0));
  legend->setLabelColor(chart_colours::kLabel);
  legend->setMarkerShape(QLegend::MarkerShapeFromSeries);
}

void styleAxis(QAbstractAxis* axis, const QFont& baseFont) {
  axis->setLabelsFont(sizedFont(baseFont, 8.0));
  axis->setLabelsBrush(chart_colours::kLabel);
  axis->setTitleFont(sizedFont(baseFont, 8.0));
  axis->setTitleBrush(chart_colours::kLabel);
  // One-pixel pens: Qt draws those directly instead of stroking an outline each frame.
  axis->setGridLinePen(QPen(chart_colours::kGrid, 1.0));
  axis->setLinePen(QPen(chart_colours::kAxisLine, 1.0));
  axis->setMinorGridLineVisible(false);
  axis->setShadesVisible(false);
}

void styleAxis(QValueAxis* axis, const QFont& baseFont) {
  axis->setTickType(QValueAxis::TicksDynamic);
  axis->setTickAnchor(0.0);
  styleAxis(static_cast<QAbstractAxis*>(axis), baseFont);
}

void applyScale(QValueAxis* axis, const AxisScale& scale, const QString& labelFormat) {
  // Every change relays the ticks out: in between, the new range must not meet the old, finer
  // interval (a range 10⁵ times wider would create 10⁵ tick items). Widen the interval before
  // the range, narrow it after.
  if (axis->tickType() != QValueAxis::TicksDynamic) {
    // Fixed ticks (a chart sets them while it swaps series, as attaching one resets the
    // range) are a handful whatever the range: set both, then go back to ticks at round values.
    axis->setRange(scale.min, scale.max);
    axis->setTickInterval(scale.tickInterval);
    axis->setTickType(QValueAxis::TicksDynamic);
  } else if (scale.tickInterval >= axis->tickInterval()) {
    axis->setTickInterval(scale.tickInterval);
    axis->setRange(scale.min, scale.max);
  } else {
    axis->setRange(scale.min, scale.max);
    axis->setTickInterval(scale.tickInterval);
  }
  axis->setLabelFormat(labelFormat);
}

QString quantityName(Quantity quantity) {
  switch (quantity) {
    case Quantity::MomentumX:
      return QStringLiteral("px");
    case Quantity::MomentumY:
      return QStringLiteral("py");
    case Quantity::MomentumMagnitude:
      return QStringLiteral("|p|");
    case Quantity::KineticEnergy:
      return QStringLiteral("kinetic");
    case Quantity::PotentialEnergy:
      return QStringLiteral("potential");
    case Quantity::TotalEnergy:
      return QStringLiteral("total");
    case Quantity::EnergyResidual:
      return QStringLiteral("residual");
    case Quantity::RelativeEnergyResidual:
      return QStringLiteral("residual / |E₀|");
    case Quantity::RmsPositionDifference:
      return QStringLiteral("RMS Δposition");
    case Quantity::MaxPositionDifference:
      return QStringLiteral("max Δposition");
  }
  return {};
}

}  // namespace fooball::gui
