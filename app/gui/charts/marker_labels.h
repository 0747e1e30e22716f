#pragma once

#include <QRectF>
#include <optional>
#include <vector>

namespace fooball::gui {

/// A marker's label to place: its line's x (px) and the label's size.
struct MarkerLabelRequest {
  double x = 0.0;
  double width = 0.0;
};

/// Where the markers' labels go along the top of `plot`: beside the marker's line, right of it
/// or (near the plot's right edge, or when the right is taken) left of it, in the first of `rows`
/// rows of `rowHeight` px where it overlaps no other label by less than `gap` px. Every label is
/// inside the plot and no two intersect; a label with no room anywhere is left out (nullopt).
/// Markers may come in any order: the earlier ones (by x) are placed first.
std::vector<std::optional<QRectF>> layoutMarkerLabels(const std::vector<MarkerLabelRequest>& labels,
                                                      const QRectF& plot, double rowHeight,
                                                      int rows, double gap);

}  // namespace fooball::gui
