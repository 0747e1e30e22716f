#pragma once

#include <QRect>
#include <QSize>
#include <vector>

#include "fooball/scene.h"

namespace fooball::gui {

/// Side by side: the tiles' columns and rows.
struct TileGrid {
  int columns = 1;
  int rows = 1;
};

/// The grid whose tiles show `box` largest in `area`, each tile keeping the box's aspect ratio
/// with `margin` px around it; on a tie the squarer grid (2 runs 1×2, 3–4 runs 2×2, 5–6 2×3).
TileGrid tileGrid(int tiles, QSize area, const Box& box, int margin);

/// The captions of a view (legend entries, hints) laid out in rows across the top of `area`,
/// outside the box: `leading` ones from the left, `trailing` ones from the right, in order,
/// `gap` px apart, a row wrapping when the next caption does not fit.
struct CaptionRows {
  std::vector<QRect> leading;
  std::vector<QRect> trailing;
  int height = 0;  ///< px from area's top to below the last row, `gap` included
};
CaptionRows layoutCaptionRows(const QRect& area, const std::vector<QSize>& leading,
                              const std::vector<QSize>& trailing, int gap);

}  // namespace fooball::gui
