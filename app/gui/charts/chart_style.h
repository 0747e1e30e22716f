#pragma once

#include <QColor>
#include <QPen>
#include <QString>

#include "chart_sample.h"

namespace fooball::gui {

/// A run's colour in compare mode: warm for run 0, cool for run 1.
QColor runColour(int runIndex);

/// The pen of `quantity`'s curve for run `runIndex` of `runCount`. With one run each quantity
/// has its own colour; with two the colour says the run and the line style says the quantity
/// (solid for the headline quantity of a chart, dashed and dotted for its parts). Headlines
/// are heavier than parts.
QPen curvePen(Quantity quantity, int runIndex, int runCount);

/// The short name of a quantity in a legend: "px", "kinetic", …
QString quantityName(Quantity quantity);

/// The colours around the curves: a near-black plot like the simulation view, grey text.
namespace chart_colours {
inline const QColor kBackground{0x16, 0x17, 0x1c};
inline const QColor kPlotArea{0x05, 0x05, 0x07};
inline const QColor kGrid{0x2c, 0x2e, 0x36};
inline const QColor kAxisLine{0x55, 0x58, 0x63};
inline const QColor kLabel{0xb4, 0xb7, 0xc0};
inline const QColor kTitle{0xe6, 0xe7, 0xeb};
inline const QColor kMarker{0xff, 0xff, 0xff, 0x70};
inline const QColor kMarkerLabelBackground{0x10, 0x10, 0x14, 0xd0};
}  // namespace chart_colours

}  // namespace fooball::gui
