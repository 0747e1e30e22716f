#pragma once

#include <QColor>
#include <QPen>
#include <QString>

#include "chart_sample.h"

namespace fooball::gui {

/// A run's colour in compare mode, for runs 0 to 7 (RunGroup::kMaxRuns); others repeat them.
/// Eight hues far apart, all light enough to read on the near-black plot and on the black
/// simulation view, none of them grey (the baseline's) or white (markers, the single-run total).
QColor runColour(int runIndex);
/// The chaos baseline's colour: a neutral grey that no run has.
QColor baselineColour();

/// The pen of `quantity`'s curve for run `runIndex`. With one run (`colourByRun` false) each
/// quantity has its own colour; in compare mode the colour says the run and the line style says
/// the quantity (solid for the headline quantity of a chart, dashed and dotted for its parts).
/// Headlines are heavier than parts.
QPen curvePen(Quantity quantity, int runIndex, bool colourByRun);
/// The chaos baseline's curve: grey and dashed, so it reads as a reference line, not a run.
QPen baselinePen();

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
