#include "toggle_icon.h"

#include <QPainter>
#include <QPainterPath>
#include <QPixmap>
#include <algorithm>

namespace fooball::gui {
namespace {

constexpr int kIconSize = 16;                  // px
const QColor kEdge{0xb4, 0xb7, 0xc0};          // 8:1 on the window's #202229
const QColor kDisabledEdge{0x6a, 0x6e, 0x7a};  // still 3:1, the least for a control's outline
const QColor kFill{0x2f, 0x6f, 0xd0};          // the palette's highlight
const QColor kMark{0xff, 0xff, 0xff};

QPixmap drawToggle(bool on, qreal pixelRatio) {
  QPixmap pixmap(QSize(kIconSize, kIconSize) * pixelRatio);
  pixmap.setDevicePixelRatio(pixelRatio);
  pixmap.fill(Qt::transparent);
  QPainter painter(&pixmap);
  paintCheckBox(painter, QRectF(2.0, 2.0, kIconSize - 4.0, kIconSize - 4.0),
                on ? Qt::Checked : Qt::Unchecked, true);
  return pixmap;
}

}  // namespace

void paintCheckBox(QPainter& painter, const QRectF& box, Qt::CheckState state, bool enabled) {
  painter.save();
  painter.setRenderHint(QPainter::Antialiasing);
  const QRectF frame = box.adjusted(0.75, 0.75, -0.75, -0.75);
  const QColor fill = enabled ? kFill : kDisabledEdge;
  const bool marked = state != Qt::Unchecked;
  painter.setPen(QPen(marked ? fill : (enabled ? kEdge : kDisabledEdge), 1.5));
  painter.setBrush(marked ? QBrush(fill) : QBrush(Qt::NoBrush));
  painter.drawRoundedRect(frame, 2.0, 2.0);
  const double inset = std::max(2.0, frame.width() * 0.22);
  const QRectF mark = frame.adjusted(inset, inset, -inset, -inset);
  painter.setPen(
      QPen(kMark, std::max(1.5, frame.width() * 0.16), Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
  painter.setBrush(Qt::NoBrush);
  if (state == Qt::Checked) {
    QPainterPath tick;
    tick.moveTo(mark.left(), mark.center().y());
    tick.lineTo(mark.left() + mark.width() * 0.4, mark.bottom());
    tick.lineTo(mark.right(), mark.top());
    painter.drawPath(tick);
  } else if (state == Qt::PartiallyChecked) {
    painter.drawLine(QPointF(mark.left(), mark.center().y()),
                     QPointF(mark.right(), mark.center().y()));
  }
  painter.restore();
}

void paintRadioButton(QPainter& painter, const QRectF& box, bool on, bool enabled) {
  painter.save();
  painter.setRenderHint(QPainter::Antialiasing);
  const double side = std::min(box.width(), box.height());
  const QRectF circle(box.center().x() - side / 2.0 + 0.75, box.center().y() - side / 2.0 + 0.75,
                      side - 1.5, side - 1.5);
  painter.setPen(QPen(on && enabled ? kFill : (enabled ? kEdge : kDisabledEdge), 1.5));
  painter.setBrush(Qt::NoBrush);
  painter.drawEllipse(circle);
  if (on) {
    painter.setPen(Qt::NoPen);
    painter.setBrush(enabled ? kFill : kDisabledEdge);
    const double dot = side * 0.27;
    painter.drawEllipse(circle.center(), dot, dot);
  }
  painter.restore();
}

QIcon toggleIcon() {
  QIcon icon;
  for (const qreal ratio : {1.0, 2.0}) {
    icon.addPixmap(drawToggle(true, ratio), QIcon::Normal, QIcon::On);
    icon.addPixmap(drawToggle(false, ratio), QIcon::Normal, QIcon::Off);
  }
  return icon;
}

}  // namespace fooball::gui
