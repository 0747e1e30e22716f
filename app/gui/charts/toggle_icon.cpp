#include "toggle_icon.h"

#include <QPainter>
#include <QPainterPath>
#include <QPixmap>

namespace fooball::gui {
namespace {

constexpr int kIconSize = 16;  // px
const QColor kBoxEdge{0xb4, 0xb7, 0xc0};
const QColor kTickFill{0x2f, 0x6f, 0xd0};
const QColor kTick{0xff, 0xff, 0xff};

QPixmap drawBox(bool ticked, qreal pixelRatio) {
  QPixmap pixmap(QSize(kIconSize, kIconSize) * pixelRatio);
  pixmap.setDevicePixelRatio(pixelRatio);
  pixmap.fill(Qt::transparent);
  QPainter painter(&pixmap);
  painter.setRenderHint(QPainter::Antialiasing);
  const QRectF box(2.5, 2.5, kIconSize - 5.0, kIconSize - 5.0);
  painter.setPen(QPen(ticked ? kTickFill : kBoxEdge, 1.5));
  painter.setBrush(ticked ? QBrush(kTickFill) : QBrush(Qt::NoBrush));
  painter.drawRoundedRect(box, 2.0, 2.0);
  if (ticked) {
    QPainterPath tick;
    tick.moveTo(box.left() + 2.5, box.center().y());
    tick.lineTo(box.center().x() - 0.5, box.bottom() - 2.5);
    tick.lineTo(box.right() - 2.0, box.top() + 2.5);
    painter.setPen(QPen(kTick, 2.0, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    painter.setBrush(Qt::NoBrush);
    painter.drawPath(tick);
  }
  return pixmap;
}

}  // namespace

QIcon toggleIcon() {
  QIcon icon;
  for (const qreal ratio : {1.0, 2.0}) {
    icon.addPixmap(drawBox(true, ratio), QIcon::Normal, QIcon::On);
    icon.addPixmap(drawBox(false, ratio), QIcon::Normal, QIcon::Off);
  }
  return icon;
}

}  // namespace fooball::gui
