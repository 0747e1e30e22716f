#include "series_points.h"

#include <algorithm>
#include <cmath>

namespace fooball::gui {

ValueRange fillSeriesPoints(const SampleHistory& history, Quantity quantity, double timeStart,
                            double timeEnd, int maxPoints, QList<QPointF>& points,
                            bool positiveOnly) {
  points.clear();
  const auto kept = [positiveOnly](double value) {
    return std::isfinite(value) && (!positiveOnly || value > 0.0);
  };
  ValueRange range;
  if (history.valueCountSince(timeStart) <= static_cast<std::size_t>(maxPoints)) {
    history.forEachValueSince(timeStart, quantity, [&](double time, double value) {
      if (!kept(value)) return;
      points.append(QPointF(time, value));
      range.include(value);
    });
    return range;
  }

  const int binCount = std::max(1, maxPoints / 2);
  const double binsPerSecond = binCount / std::max(timeEnd - timeStart, 1e-300);
  int currentBin = -1;
  QPointF lowest;
  QPointF highest;
  const auto flushBin = [&] {
    if (currentBin < 0) return;
    // The bin's extremes in time order; one point when a single value is both.
    const bool lowestFirst = lowest.x() <= highest.x();
    points.append(lowestFirst ? lowest : highest);
    if (lowest != highest) points.append(lowestFirst ? highest : lowest);
    range.include(lowest.y());
    range.include(highest.y());
  };
  history.forEachValueSince(timeStart, quantity, [&](double time, double value) {
    if (!kept(value)) return;
    const double binPosition = std::floor((time - timeStart) * binsPerSecond);
    const int bin = static_cast<int>(std::clamp(binPosition, 0.0, binCount - 1.0));
    if (bin != currentBin) {
      flushBin();
      currentBin = bin;
      lowest = highest = QPointF(time, value);
    } else if (value < lowest.y()) {
      lowest = QPointF(time, value);
    } else if (value > highest.y()) {
      highest = QPointF(time, value);
    }
  });
  flushBin();
  return range;
}

}  // namespace fooball::gui
