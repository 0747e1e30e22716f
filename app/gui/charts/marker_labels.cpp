#include "marker_labels.h"

#include <algorithm>
#include <numeric>

namespace fooball::gui {
namespace {

/// px between a marker's line and its label.
constexpr double kLineGap = 2.0;

}  // namespace

std::vector<std::optional<QRectF>> layoutMarkerLabels(const std::vector<MarkerLabelRequest>& labels,
                                                      const QRectF& plot, double rowHeight,
                                                      int rows, double gap) {
  std::vector<std::optional<QRectF>> placed(labels.size());
  std::vector<std::size_t> order(labels.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return labels[a].x < labels[b].x; });
  std::vector<std::vector<QRectF>> taken(std::size_t(std::max(rows, 0)));
  const auto isFree = [&](const QRectF& rect, const std::vector<QRectF>& row) {
    if (rect.left() < plot.left() || rect.right() > plot.right()) return false;
    const QRectF padded = rect.adjusted(-gap, 0.0, gap, 0.0);
    return std::none_of(row.begin(), row.end(),
                        [&](const QRectF& other) { return padded.intersects(other); });
  };
  for (const std::size_t index : order) {
    const MarkerLabelRequest& label = labels[index];
    if (label.width > plot.width()) continue;
    for (std::size_t row = 0; row < taken.size() && !placed[index]; ++row) {
      const double top = plot.top() + kLineGap + double(row) * rowHeight;
      for (const double left : {label.x + kLineGap, label.x - kLineGap - label.width}) {
        const QRectF rect(left, top, label.width, rowHeight);
        if (!isFree(rect, taken[row])) continue;
        taken[row].push_back(rect);
        placed[index] = rect;
        break;
      }
    }
  }
  return placed;
}

}  // namespace fooball::gui
