#include "chart_style.h"

#include <QList>
#include <array>

#include "fooball/run_group.h"

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

QColor runColour(int runIndex) {
  // Runs 0 and 1 keep the colours two-run compare mode always had. The rest go round the hue
  // circle between them, alternating warm and cool so that neighbouring runs differ most.
  static const std::array<QColor, 8> kColours{
      QColor(0xff, 0xa7, 0x26),  // orange
      QColor(0x26, 0xc6, 0xda),  // cyan
      QColor(0xe0, 0x40, 0xfb),  // magenta
      QColor(0x9c, 0xe0, 0x4c),  // lime
      QColor(0xff, 0x52, 0x52),  // red
      QColor(0x5c, 0x8d, 0xff),  // blue
      QColor(0xff, 0xee, 0x58),  // yellow
      QColor(0x69, 0xf0, 0xae),  // green
  };
  static_assert(kColours.size() == RunGroup::kMaxRuns);
  const auto count = static_cast<int>(kColours.size());
  return kColours[static_cast<std::size_t>(((runIndex % count) + count) % count)];
}

QColor baselineColour() {
  return QColor(0x9e, 0x9e, 0x9e);
}

QPen baselinePen() {
  // As heavy as a run's headline curve, so it can be followed at a glance; the dashes say it is
  // a reference, not a method.
  QPen pen(baselineColour(), 2.0);
  pen.setDashPattern({4.0, 3.0});
  return pen;
}

QPen curvePen(Quantity quantity, int runIndex, bool colourByRun) {
  const QuantityLook look = lookOf(quantity);
  const QColor colour = colourByRun ? runColour(runIndex) : look.singleRunColour;
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
