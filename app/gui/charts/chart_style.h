#pragma once

#include <QColor>
#include <QMargins>
#include <QPen>
#include <QString>

#include "axis_scale.h"
#include "chart_sample.h"

class QAbstractAxis;
class QChart;
class QFont;
class QValueAxis;

namespace fooball::gui {

/// The pen of `quantity`'s curve for run `runIndex`. With one run (`colourByRun` false) each
/// quantity has its own colour; in compare mode the colour says the run (colours::runColour) and
/// the line style says the quantity (solid for the headline quantity of a chart, dashed and dotted
/// for its parts). Headlines are heavier than parts.
QPen curvePen(Quantity quantity, int runIndex, bool colourByRun);
/// The chaos baseline's curve: grey and dashed, so it reads as a reference line, not a run.
QPen baselinePen();

/// The short name of a quantity in a legend: "px", "kinetic", …
QString quantityName(Quantity quantity);

/// `base` at `pointSize`: the charts' titles are 9 pt bold, their legends and axes 8 pt.
QFont sizedFont(const QFont& base, double pointSize, bool bold = false);
/// The look every live chart shares: the dark theme, the colours below, no animation, no
/// layout margins, `title` in 9 pt bold and the legend on top in 8 pt. The chart's own margins
/// are the caller's.
void styleChart(QChart* chart, const QString& title, const QFont& baseFont);
/// Axis labels and titles in 8 pt grey, one-pixel grid and axis lines, no minor grid.
void styleAxis(QAbstractAxis* axis, const QFont& baseFont);
/// The same, with ticks at round values from 0 (TicksDynamic, anchored at 0).
void styleAxis(QValueAxis* axis, const QFont& baseFont);

/// px around a live chart's plot (QChart::setMargins): room for the last label on the right.
inline const QMargins kChartMargins(4, 2, 12, 2);

/// Sets `axis` to `scale` with tick labels in `labelFormat` (printf style). In between, the new
/// range never meets the old, finer interval, which could make 10⁵ tick items.
void applyScale(QValueAxis* axis, const AxisScale& scale, const QString& labelFormat);

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
