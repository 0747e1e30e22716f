#include "view/view_transform.h"

#include <algorithm>
#include <cmath>

namespace fooball::gui {

ViewTransform::ViewTransform(const Box& box, const QRect& area, int margin) : height_(box.height) {
  const QRect inner = area.adjusted(margin, margin, -margin, -margin);
  const double fit = std::min(double(std::max(inner.width(), 1)) / box.width,
                              double(std::max(inner.height(), 1)) / box.height);
  const int width = std::max(1, static_cast<int>(std::floor(box.width * fit)));
  const int height = std::max(1, static_cast<int>(std::floor(box.height * fit)));
  // Whole pixels for the box; the scale follows from its width so x and y stay equal.
  scale_ = double(width) / box.width;
  boxRect_ = QRect(inner.left() + (inner.width() - width) / 2,
                   inner.top() + (inner.height() - height) / 2, width, height);
}

}  // namespace fooball::gui
