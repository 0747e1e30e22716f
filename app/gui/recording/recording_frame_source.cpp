#include "recording_frame_source.h"

#include <QDockWidget>
#include <QPainter>
#include <algorithm>

#include "charts/chart_panel.h"
#include "view/simulation_view.h"

namespace fooball::gui {

namespace {

bool chartsShown(const RecordingTarget& target, RecordArea area) {
  return area == RecordArea::BoxAndCharts && target.chartsDock.isVisible() &&
         target.charts.isVisible();
}

/// Where the charts go in the picture: where they are in the window, in a column to the box's
/// right (taller than wide) or in a strip under it.
bool chartsBeside(const RecordingTarget& target) {
  return target.charts.height() > target.charts.width();
}

}  // namespace

RecordingFrameSource::RecordingFrameSource(const RecordingTarget& target, RecordArea area,
                                           QSize videoSize)
    : target_(target),
      area_(area),
      canvas_(videoSize, QImage::Format_RGB32),
      image_(videoSize, QImage::Format_RGB888) {}

QSize RecordingFrameSource::shownSize(const RecordingTarget& target, RecordArea area) {
  QSize size = target.view.size();
  if (chartsShown(target, area)) {
    const QSize charts = target.charts.size();
    size = chartsBeside(target)
               ? QSize(size.width() + charts.width(), std::max(size.height(), charts.height()))
               : QSize(std::max(size.width(), charts.width()), size.height() + charts.height());
  }
  return size;
}

const QImage& RecordingFrameSource::grab() {
  const QSize shown = shownSize(target_, area_);
  canvas_.fill(Qt::black);
  if (!shown.isEmpty()) {
    QPainter painter(&canvas_);
    painter.setRenderHints(QPainter::Antialiasing | QPainter::SmoothPixmapTransform |
                           QPainter::TextAntialiasing);
    const double scale = std::min(double(canvas_.width()) / shown.width(),
                                  double(canvas_.height()) / shown.height());
    painter.translate((canvas_.width() - scale * shown.width()) / 2.0,
                      (canvas_.height() - scale * shown.height()) / 2.0);
    painter.scale(scale, scale);
    target_.view.render(&painter);
    if (chartsShown(target_, area_)) {
      // Redrawn for every frame rather than by the panel's 10-per-second timer, so a recording
      // shows the charts as of its own frames, however fast the machine.
      target_.charts.refresh();
      painter.translate(chartsBeside(target_) ? QPoint(target_.view.width(), 0)
                                              : QPoint(0, target_.view.height()));
      target_.charts.render(&painter, QPoint(), QRegion(),
                            QWidget::DrawWindowBackground | QWidget::DrawChildren);
    }
  }
  image_ = canvas_.convertToFormat(QImage::Format_RGB888);
  return image_;
}

}  // namespace fooball::gui
