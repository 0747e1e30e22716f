#include "view/view_layout.h"

#include <algorithm>
#include <cmath>

namespace fooball::gui {

TileGrid tileGrid(int tiles, QSize area, const Box& box, int margin) {
  // On a tie (a 16:9 box in a 16:9 view fits 1×2 and 2×1 alike) the squarer grid wins.
  TileGrid best;
  double bestScale = -1.0;
  const int preferred = static_cast<int>(std::ceil(std::sqrt(double(tiles))));
  for (int offset = 0; offset < tiles; ++offset) {
    for (const int columns : {preferred + offset, preferred - offset}) {
      if (columns < 1 || columns > tiles) continue;
      const int rows = (tiles + columns - 1) / columns;
      const double scale = std::min((area.width() / double(columns) - 2 * margin) / box.width,
                                    (area.height() / double(rows) - 2 * margin) / box.height);
      if (scale > bestScale * (1.0 + 1e-9)) {
        bestScale = scale;
        best = {columns, rows};
      }
    }
  }
  return best;
}

CaptionRows layoutCaptionRows(const QRect& area, const std::vector<QSize>& leading,
                              const std::vector<QSize>& trailing, int gap) {
  // Each caption goes into the current row while the row's captions and the gaps between them
  // fit the width; a caption wider than the whole row gets a row of its own.
  struct Placed {
    bool isLeading;
    std::size_t index;
    QSize size;
  };
  std::vector<std::vector<Placed>> rows(1);
  int rowWidth = 0;
  const int width = std::max(area.width() - 2 * gap, 1);
  const auto place = [&](bool isLeading, std::size_t index, QSize size) {
    size.setWidth(std::min(size.width(), width));  // the painter elides what is cut
    if (!rows.back().empty() && rowWidth + gap + size.width() > width) {
      rows.emplace_back();
      rowWidth = 0;
    }
    rowWidth += (rows.back().empty() ? 0 : gap) + size.width();
    rows.back().push_back({isLeading, index, size});
  };
  for (std::size_t i = 0; i < leading.size(); ++i)
    place(true, i, leading[i]);
  for (std::size_t i = 0; i < trailing.size(); ++i)
    place(false, i, trailing[i]);

  CaptionRows result;
  result.leading.resize(leading.size());
  result.trailing.resize(trailing.size());
  int top = area.top() + gap;
  for (const std::vector<Placed>& row : rows) {
    int rowHeight = 0;
    for (const Placed& placed : row)
      rowHeight = std::max(rowHeight, placed.size.height());
    int left = area.left() + gap;
    int right = area.right() + 1 - gap;
    // Trailing captions fill from the right edge, the last one rightmost.
    for (auto it = row.rbegin(); it != row.rend(); ++it) {
      if (it->isLeading) continue;
      right -= it->size.width();
      result.trailing[it->index] = QRect(QPoint(right, top), it->size);
      right -= gap;
    }
    for (const Placed& placed : row) {
      if (!placed.isLeading) continue;
      result.leading[placed.index] = QRect(QPoint(left, top), placed.size);
      left += placed.size.width() + gap;
    }
    top += rowHeight + gap;
  }
  result.height = rows.front().empty() ? 0 : top - area.top();
  return result;
}

}  // namespace fooball::gui
