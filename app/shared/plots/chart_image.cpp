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

namespace fooball::plots {

namespace {

/// Labelled intervals on a log axis at the most: about 40 px each on a panel 320 px high.
constexpr int kMostLabelIntervals = 6;
/// The lowest top a log axis may have (as a power of ten). Qt Charts 6.4 draws neither value
/// labels nor title on a log axis spanning less than about 1e-11 (measured: 1e-17 to 1e-14
/// shows nothing, 1e-17 to 1e-11 every label), as an energy panel of exact-to-rounding
/// methods would be.
constexpr int kLeastTopExponent = -11;
/// Qt rounds log10 of the axis' bottom up past its decade and drops that label (1e-4 and 1e-13
/// went unlabelled): a hair below it keeps the label.
constexpr double kBottomNudge = 1.0 - 1e-9;

}  // namespace

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
  // No data, or none a log axis can show: one decade from 1.
  if (!(low > 0.0) || !std::isfinite(low)) low = 1.0;
  if (!(high >= low) || !std::isfinite(high)) high = low;
  // The decade exponents of doubles are within ±324: ints hold them.
  int bottom = static_cast<int>(std::floor(std::log10(low)));
  int top =
      std::max({static_cast<int>(std::ceil(std::log10(high))), bottom + 1, kLeastTopExponent});
  // Qt labels every power of the base, and elides them all to "…" when they crowd (a panel of
  // 17 decades, an exact method's zero error beside percent-level ones): over many decades the
  // base is 10^k, labelling every k-th decade, with both ends on a labelled one.
  const int decadesPerLabel = (top - bottom + kMostLabelIntervals - 1) / kMostLabelIntervals;
  bottom = decadesPerLabel * static_cast<int>(std::floor(double(bottom) / decadesPerLabel));
  top = decadesPerLabel * static_cast<int>(std::ceil(double(top) / decadesPerLabel));
  axis->setBase(std::pow(10.0, decadesPerLabel));
  axis->setRange(std::pow(10.0, bottom) * kBottomNudge, std::pow(10.0, top));
  // Minor lines at 2…9 help read a few decades; across many they only add noise.
  const bool fewDecades = top - bottom <= 3;
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
