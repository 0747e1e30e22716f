#pragma once

#include <QList>
#include <QPointF>

#include "axis_scale.h"
#include "chart_sample.h"
#include "sample_history.h"

namespace fooball::gui {

/// Fills `points` (cleared first; its capacity is reused) with `quantity` against time from
/// `history`, for a line on a time axis from `timeStart` to `timeEnd` (s). When the history
/// has more than `maxPoints` values there, the axis is cut into maxPoints / 2 equal time bins
/// and each bin keeps its lowest and its highest value, so a spike survives decimation and no
/// point is stretched over more time than its neighbours. Non-finite values are left out, and
/// with `positiveOnly` (for a log axis) values ≤ 0 too. Returns the range of the values kept.
ValueRange fillSeriesPoints(const SampleHistory& history, Quantity quantity, double timeStart,
                            double timeEnd, int maxPoints, QList<QPointF>& points,
                            bool positiveOnly = false);

}  // namespace fooball::gui
