#include "chart_style.h"

#include <QList>

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
  }
  return {Qt::white, 0};
}

}  // namespace

QColor runColour(int runIndex) {
  return runIndex == 0 ? QColor(0xff, 0xa7, 0x26) : QColor(0x26, 0xc6, 0xda);
}

QPen curvePen(Quantity quantity, int runIndex, int runCount) {
  const QuantityLook look = lookOf(quantity);
  const QColor colour = runCount < 2 ? look.singleRunColour : runColour(runIndex);
  // The headline curve is heavier, so the eye finds it first.
  if (look.rank == 0) return QPen(colour, 2.0);
  // The parts are one pixel wide: Qt draws such lines directly, where a wider pen is stroked
  // into an outline first, which over thousands of points costs milliseconds a frame. Not
  // cosmetic, so an export at twice the pixels draws them twice as wide, like everything else.
  QPen pen(colour, 1.0);
  // With two runs the colour says the run, so the line style says the part: dashed for the
  // first, dotted for the second (patterns in pen widths).
  if (runCount >= 2) {
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
  }
  return {};
}

}  // namespace fooball::gui
