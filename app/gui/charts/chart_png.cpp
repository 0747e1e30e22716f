#include "chart_png.h"

#include <QFontMetrics>
#include <QImage>
#include <QPainter>
#include <QWidget>

#include "chart_style.h"

namespace fooball::gui {

namespace {

/// An exported PNG has twice the on-screen pixels, sharp enough for a page or a README.
constexpr qreal kExportPixelRatio = 2.0;
constexpr int kCaptionPadding = 8;  // px around an exported image's caption

}  // namespace

bool writeChartPng(const QString& path, QWidget& chartArea, const QString& caption) {
  // The caption above the charts names what they show, so the image explains itself when it is
  // pasted somewhere else; it wraps at the image's width.
  QFont captionFont = chartArea.font();
  captionFont.setPointSizeF(captionFont.pointSizeF() * 1.1);
  const int width = chartArea.width();
  const QRect textBounds(kCaptionPadding, kCaptionPadding, width - 2 * kCaptionPadding, 10'000);
  const QRect captionRect =
      QFontMetrics(captionFont).boundingRect(textBounds, Qt::AlignLeft | Qt::TextWordWrap, caption);
  const int captionHeight = caption.isEmpty() ? 0 : captionRect.height() + 2 * kCaptionPadding;

  QImage image(QSize(width, chartArea.height() + captionHeight) * kExportPixelRatio,
               QImage::Format_ARGB32_Premultiplied);
  image.setDevicePixelRatio(kExportPixelRatio);
  image.fill(chart_colours::kBackground);
  {
    QPainter painter(&image);
    painter.setFont(captionFont);
    painter.setPen(chart_colours::kTitle);
    painter.drawText(textBounds, Qt::AlignLeft | Qt::TextWordWrap, caption);
  }
  chartArea.render(&image, QPoint(0, captionHeight));
  // The caption as text too, for whoever reads the file's metadata.
  image.setText(QStringLiteral("Description"), caption);
  return image.save(path, "PNG");
}

}  // namespace fooball::gui
