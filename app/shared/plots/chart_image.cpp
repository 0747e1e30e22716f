#include "chart_image.h"

#include <QChart>
#include <QChartView>
#include <QHBoxLayout>
#include <QLabel>
#include <QLegendMarker>
#include <QLogValueAxis>
#include <QPixmap>
#include <QVBoxLayout>
#include <QWidget>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "registry.h"

namespace fooball::plots {

QColor backendColor(std::string_view backend) {
  static const QColor kPalette[] = {QColor(0xe0, 0xa0, 0x30), QColor(0x3a, 0x7c, 0xc8),
                                    QColor(0x3c, 0xa0, 0x55), QColor(0xb0, 0x4a, 0xb0),
                                    QColor(0x80, 0x80, 0x80)};
  constexpr std::size_t kColors = std::size(kPalette);
  std::size_t index = 0;
  for (const BackendInfo& info : registeredBackends()) {
    if (info.name == backend) return kPalette[std::min(index, kColors - 1)];
    ++index;
  }
  return kPalette[kColors - 1];
}

double decadeBelow(double value) {
  return std::pow(10.0, std::floor(std::log10(value)));
}
double decadeAbove(double value) {
  return std::pow(10.0, std::ceil(std::log10(value)));
}

void addSeries(QChart* chart, QAbstractSeries* series, QAbstractAxis* x, QAbstractAxis* y,
               bool inLegend) {
  chart->addSeries(series);
  series->attachAxis(x);
  series->attachAxis(y);
  if (!inLegend) {
    for (QLegendMarker* marker : chart->legend()->markers(series))
      marker->setVisible(false);
  }
}

QLogValueAxis* decadeAxis(const QString& title, double low, double high, const char* labelFormat) {
  auto* axis = new QLogValueAxis;
  axis->setTitleText(title);
  axis->setLabelFormat(labelFormat);
  axis->setBase(10.0);
  const double bottom = decadeBelow(low);
  const double top = std::max(decadeAbove(high), 10.0 * bottom);
  axis->setRange(bottom, top);
  // Minor lines at 2…9 help read a few decades; across many they only add noise.
  const bool fewDecades = top / bottom <= 1e3;
  axis->setMinorTickCount(fewDecades ? 8 : 0);
  axis->setGridLineVisible(true);
  axis->setMinorGridLineVisible(fewDecades);
  return axis;
}

void saveCharts(std::vector<QChart*> charts, const QString& title, int chartWidth, int height,
                const std::filesystem::path& path) {
  QWidget page;
  page.setAttribute(Qt::WA_DontShowOnScreen);
  page.setStyleSheet("background: white;");
  auto* column = new QVBoxLayout(&page);
  auto* heading = new QLabel(title);
  QFont font = heading->font();
  font.setPointSize(font.pointSize() + 3);
  font.setBold(true);
  heading->setFont(font);
  heading->setAlignment(Qt::AlignCenter);
  column->addWidget(heading);
  auto* row = new QHBoxLayout;
  column->addLayout(row);
  for (QChart* chart : charts) {
    auto* view = new QChartView(chart);  // the view owns the chart
    view->setRenderHint(QPainter::Antialiasing);
    view->setFixedSize(chartWidth, height);
    row->addWidget(view);
  }
  page.show();  // lays the page out; WA_DontShowOnScreen keeps it off any screen
  const QPixmap image = page.grab();
  const QString file = QString::fromStdString(path.string());
  if (!image.save(file, "PNG")) {
    throw std::runtime_error(path.string() + ": cannot write the chart image");
  }
}

}  // namespace fooball::plots
