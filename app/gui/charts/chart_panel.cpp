#include "chart_panel.h"

#include <QAction>
#include <QChart>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QImage>
#include <QLabel>
#include <QPainter>
#include <QPalette>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QTextDocument>
#include <QTimer>
#include <QToolBar>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <vector>

#include "chart_csv.h"
#include "chart_style.h"
#include "run_palette.h"
#include "time_chart.h"
#include "toggle_icon.h"

namespace fooball::gui {
namespace {

/// ms between redraws while samples come in: 10 per second looks live, and a redraw of all
/// curves costs a few ms of the GUI thread the simulation also runs on.
constexpr int kRefreshIntervalMs = 100;
constexpr double kDefaultWindowSeconds = 20.0;
/// An exported PNG has twice the on-screen pixels, sharp enough for a page or a README.
constexpr qreal kExportPixelRatio = 2.0;
/// px between charts in the grid.
constexpr int kChartSpacing = 2;
/// The shape a chart reads best in (width : height) and the narrowest it may get in a row of
/// several: below that its tick labels crowd out the curves.
constexpr double kChartAspect = 2.4;
constexpr int kMinChartWidth = 240;  // px
constexpr int kCaptionPadding = 8;   // px around an exported image's caption

}  // namespace

int chartColumns(int charts, QSize area) {
  // The columns that give each chart the largest plot of its preferred shape; a tie goes to
  // fewer columns (wider charts).
  int best = 1;
  double bestHeight = -1.0;
  for (int columns = 1; columns <= std::max(charts, 1); ++columns) {
    const int rows = (charts + columns - 1) / columns;
    const double cellWidth = double(area.width()) / columns;
    if (columns > 1 && cellWidth < kMinChartWidth) break;
    const double cellHeight = double(area.height()) / std::max(rows, 1);
    const double height = std::min(cellWidth / kChartAspect, cellHeight);
    if (height > bestHeight + 0.5) {
      bestHeight = height;
      best = columns;
    }
  }
  return best;
}

namespace {}  // namespace

ChartPanel::ChartPanel(QWidget* parent) : QWidget(parent) {
  const std::deque<ChartMarker>* markers = &data_.markers();
  charts_[kMomentumChart] = new TimeChart(
      tr("Momentum"), {Quantity::MomentumX, Quantity::MomentumY, Quantity::MomentumMagnitude},
      markers);
  charts_[kMomentumChart]->setValueAxisTitle(tr("momentum"), tr("N·s"));
  charts_[kEnergyChart] = new TimeChart(
      tr("Energy"), {Quantity::KineticEnergy, Quantity::PotentialEnergy, Quantity::TotalEnergy},
      markers);
  charts_[kEnergyChart]->setValueAxisTitle(tr("energy"), tr("J"));
  charts_[kResidualChart] =
      new TimeChart(tr("Energy budget residual: the method's own error"),
                    {Quantity::EnergyResidual, Quantity::RelativeEnergyResidual}, markers);
  // Divergence grows from rounding (1e-15 m) or the baseline's 1e-9 m to the box's size: only a
  // log axis shows every run's growth at once, and where one leaves the baseline's.
  charts_[kDivergenceChart] = new TimeChart(tr("Divergence from run 0: RMS position difference"),
                                            {Quantity::RmsPositionDifference}, markers,
                                            TimeChart::ValueAxisKind::Logarithmic);
  charts_[kDivergenceChart]->setValueAxisTitle(tr("RMS Δposition"), tr("m"));

  // The charts share the panel in a grid (arrangeCharts) rather than a splitter: a wide, short
  // dock under the box fits them side by side, a tall one on top of each other.
  chartGrid_ = new QWidget(this);
  gridLayout_ = new QGridLayout(chartGrid_);
  gridLayout_->setContentsMargins(0, 0, 0, 0);
  gridLayout_->setSpacing(kChartSpacing);
  for (TimeChart* chart : charts_) {
    chart->setParent(chartGrid_);
    connect(chart->chart(), &QChart::plotAreaChanged, this, &ChartPanel::alignPlotAreas);
  }
  QPalette chartPalette = palette();
  chartPalette.setColor(QPalette::Window, chart_colours::kBackground);

  // The run legend: one entry per run in its colour, wrapping onto more lines when the panel is
  // narrow. A chart's own legend is one row that Qt elides to "…" when eight runs do not fit.
  runLegend_ = new QLabel;
  runLegend_->setObjectName(QStringLiteral("runLegend"));
  runLegend_->setTextFormat(Qt::RichText);
  runLegend_->setWordWrap(true);
  runLegend_->setContentsMargins(8, 3, 8, 3);
  runLegend_->setToolTip(
      tr("Each run's colour. Run 0 is the reference: the divergence chart shows how far every "
         "other run's balls are from run 0's"));
  QPalette legendPalette = runLegend_->palette();
  legendPalette.setColor(QPalette::WindowText, chart_colours::kLabel);
  runLegend_->setPalette(legendPalette);

  chartArea_ = new QWidget(this);
  chartArea_->setPalette(chartPalette);
  chartArea_->setAutoFillBackground(true);
  auto* chartLayout = new QVBoxLayout(chartArea_);
  chartLayout->setContentsMargins(0, 0, 0, 0);
  chartLayout->setSpacing(0);
  chartLayout->addWidget(runLegend_);
  chartLayout->addWidget(chartGrid_, 1);

  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(0);
  layout->addWidget(createToolBar());
  // The charts scroll rather than push the window taller than the screen: four charts with
  // their titles and axes need more height than a 1000×650 window has to spare.
  scroll_ = new QScrollArea;
  scroll_->setWidget(chartArea_);
  scroll_->setWidgetResizable(true);
  scroll_->setFrameShape(QFrame::NoFrame);
  scroll_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  scroll_->viewport()->installEventFilter(this);
  layout->addWidget(scroll_, 1);

  refreshTimer_ = new QTimer(this);
  refreshTimer_->setInterval(kRefreshIntervalMs);
  connect(refreshTimer_, &QTimer::timeout, this, [this] {
    if (viewOutOfDate_ && isVisible()) refresh();
  });
  refreshTimer_->start();

  reset({});
}

ChartPanel::~ChartPanel() {
  // The charts' marker overlays read data_, which members outlive but child widgets do not.
  delete chartArea_;
}

QToolBar* ChartPanel::createToolBar() {
  auto* toolBar = new QToolBar(this);
  // Every action here is a switch: a check box beside its name says which are on.
  toolBar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
  toolBar->setIconSize(QSize(16, 16));
  const QIcon toggle = toggleIcon();

  wholeRunToggle_ = toolBar->addAction(tr("Whole run"));
  wholeRunToggle_->setObjectName(QStringLiteral("wholeRunToggle"));
  wholeRunToggle_->setCheckable(true);
  wholeRunToggle_->setIcon(toggle);
  wholeRunToggle_->setToolTip(
      tr("Show the whole run (older parts at reduced resolution) instead of a scrolling window"));
  connect(wholeRunToggle_, &QAction::toggled, this, &ChartPanel::setShowWholeRun);

  windowSpin_ = new QDoubleSpinBox(toolBar);
  windowSpin_->setObjectName(QStringLiteral("windowSeconds"));
  windowSpin_->setRange(1.0, 3600.0);
  windowSpin_->setDecimals(0);
  windowSpin_->setSuffix(tr(" s"));
  windowSpin_->setValue(kDefaultWindowSeconds);
  windowSpin_->setKeyboardTracking(false);
  windowSpin_->setToolTip(tr("Length of the scrolling window, in seconds of simulated time"));
  connect(windowSpin_, &QDoubleSpinBox::valueChanged, this, &ChartPanel::setWindowSeconds);
  toolBar->addWidget(windowSpin_);

  toolBar->addSeparator();
  momentumXToggle_ = addQuantityToggle(toolBar, tr("px"), tr("Momentum, x component: Σ m vx (N·s)"),
                                       QStringLiteral("momentumXToggle"));
  momentumYToggle_ = addQuantityToggle(toolBar, tr("py"), tr("Momentum, y component: Σ m vy (N·s)"),
                                       QStringLiteral("momentumYToggle"));
  momentumMagnitudeToggle_ =
      addQuantityToggle(toolBar, tr("|p|"), tr("Magnitude of the total momentum |Σ m v| (N·s)"),
                        QStringLiteral("momentumMagnitudeToggle"));
  toolBar->addSeparator();
  kineticToggle_ = addQuantityToggle(toolBar, tr("kinetic"), tr("Kinetic energy Σ ½ m|v|² (J)"),
                                     QStringLiteral("kineticToggle"));
  potentialToggle_ = addQuantityToggle(
      toolBar, tr("potential"), tr("Potential energy Σ −m (g·p), zero at the floor y = 0 (J)"),
      QStringLiteral("potentialToggle"));
  totalToggle_ =
      addQuantityToggle(toolBar, tr("total"), tr("Total energy: kinetic + potential (J)"),
                        QStringLiteral("totalToggle"));
  toolBar->addSeparator();
  residualToggle_ = addQuantityToggle(
      toolBar, tr("residual"),
      tr("Energy budget residual: E(t) − E(0) − work by tools and edits + energy taken by drag. "
         "What is left is the method's own error (J)"),
      QStringLiteral("residualToggle"));
  relativeResidualToggle_ = addQuantityToggle(
      toolBar, tr("÷|E₀|"),
      tr("Show the residual relative to |E₀|, the run's total energy where its budget began "
         "(load or restart)"),
      QStringLiteral("relativeResidualToggle"));
  {
    const QSignalBlocker blocker(relativeResidualToggle_);  // the toggles are not all there yet
    relativeResidualToggle_->setChecked(false);
  }
  toolBar->addSeparator();
  divergenceToggle_ = addQuantityToggle(
      toolBar, tr("divergence"),
      tr("RMS position difference of every run from run 0, over balls of the same index (m, log "
         "scale), and the chaos baseline's (grey, dashed). Shown with two runs or more, or with "
         "the baseline"),
      QStringLiteral("divergenceToggle"));
  return toolBar;
}

QAction* ChartPanel::addQuantityToggle(QToolBar* toolBar, const QString& text,
                                       const QString& toolTip, const QString& objectName) {
  QAction* toggle = toolBar->addAction(text);
  toggle->setObjectName(objectName);
  toggle->setToolTip(toolTip);
  toggle->setCheckable(true);
  toggle->setChecked(true);
  toggle->setIcon(toggleIcon());
  connect(toggle, &QAction::toggled, this, &ChartPanel::applyToggles);
  return toggle;
}

void ChartPanel::reset(const QStringList& runLabels) {
  data_.reset(runLabels);
  rebuildCurves();
}

void ChartPanel::addRun(const QString& label) {
  if (data_.runCount() >= ChartData::kMaxRuns) return;
  data_.addRun(label);
  rebuildCurves();
}

void ChartPanel::removeRun(int runIndex) {
  const int before = data_.runCount();
  data_.removeRun(runIndex);
  if (data_.runCount() != before) rebuildCurves();
}

void ChartPanel::renameRun(int runIndex, const QString& label) {
  if (runIndex < 0 || runIndex >= data_.runCount() || data_.runName(runIndex) == label) return;
  data_.renameRun(runIndex, label);
  rebuildCurves();
}

void ChartPanel::setBaselineShown(bool shown) {
  if (data_.baselineShown() == shown) return;
  data_.setBaselineShown(shown);
  rebuildCurves();
}

void ChartPanel::rebuildCurves() {
  const int runCount = data_.runCount();
  const bool comparing = runCount > 1;
  std::vector<TimeChart::CurveOwner> runs;
  std::vector<TimeChart::CurveOwner> divergent;  // run 0's divergence from itself is nothing
  for (int run = 0; run < runCount; ++run) {
    runs.push_back({run, data_.runName(run)});
    if (run > 0) divergent.push_back({run, data_.runName(run)});
  }
  // The baseline is run 0's method from a start 1e-9 m away: until chaos has grown that to
  // something visible its momentum, energy and residual lie on run 0's, and after that they
  // say nothing about the method that run 0's do not. So it is drawn on the divergence chart
  // only, where it is the yardstick, and never hides run 0's curves in the others.
  if (data_.baselineShown()) divergent.push_back({ChartData::kBaseline, tr("chaos baseline")});
  for (const Chart chart : {kMomentumChart, kEnergyChart, kResidualChart})
    charts_[chart]->setOwners(runs, comparing);
  charts_[kDivergenceChart]->setOwners(divergent, true);

  QStringList entries;
  if (comparing) {
    for (int run = 0; run < runCount; ++run) {
      const QString label =
          data_.runName(run).isEmpty() ? tr("run %1").arg(run) : data_.runName(run).toHtmlEscaped();
      entries.append(QStringLiteral("<span style='color:%1'>&#x2501;&#x2501;</span>&nbsp;%2%3")
                         .arg(colours::runColour(run).name(), label,
                              run == 0 ? tr("&nbsp;(reference)") : QString()));
    }
  }
  runLegend_->setText(entries.join(QStringLiteral(" &nbsp;&nbsp; ")));
  runLegend_->setVisible(comparing);
  applyToggles();
}

void ChartPanel::addSample(int runIndex, const fooball::Metrics& metrics,
                           const fooball::Divergence& fromRunZero) {
  if (runIndex < 0 || runIndex >= data_.runCount()) return;
  data_.addSample(runIndex, metrics, fromRunZero);
  viewOutOfDate_ = true;
}

void ChartPanel::addBaselineSample(const fooball::Metrics& metrics,
                                   const fooball::Divergence& fromRunZero) {
  if (!data_.baselineShown()) return;
  data_.addSample(ChartData::kBaseline, metrics, fromRunZero);
  viewOutOfDate_ = true;
}

void ChartPanel::addMarker(double time, const QString& label) {
  data_.addMarker(time, label);
  viewOutOfDate_ = true;
}

void ChartPanel::dropAfter(double time) {
  data_.dropAfter(time);
  viewOutOfDate_ = true;
}

void ChartPanel::replaceNewestMarker(double time, const QString& label) {
  data_.replaceNewestMarker(time, label);
  viewOutOfDate_ = true;
}

void ChartPanel::setWindowSeconds(double seconds) {
  if (!std::isfinite(seconds)) return;
  {
    const QSignalBlocker blocker(windowSpin_);
    windowSpin_->setValue(seconds);  // clamped to the spin box's range
  }
  viewOutOfDate_ = true;
  refresh();
}

void ChartPanel::setShowWholeRun(bool whole) {
  {
    const QSignalBlocker blocker(wholeRunToggle_);
    wholeRunToggle_->setChecked(whole);
  }
  windowSpin_->setEnabled(!whole);
  for (TimeChart* chart : charts_)
    chart->forgetValueScale();
  viewOutOfDate_ = true;
  refresh();
}

void ChartPanel::applyToggles() {
  const bool residualShown = residualToggle_->isChecked();
  const bool relative = relativeResidualToggle_->isChecked();
  relativeResidualToggle_->setEnabled(residualShown);

  TimeChart* momentum = charts_[kMomentumChart];
  momentum->setQuantityShown(Quantity::MomentumX, momentumXToggle_->isChecked());
  momentum->setQuantityShown(Quantity::MomentumY, momentumYToggle_->isChecked());
  momentum->setQuantityShown(Quantity::MomentumMagnitude, momentumMagnitudeToggle_->isChecked());
  TimeChart* energy = charts_[kEnergyChart];
  energy->setQuantityShown(Quantity::KineticEnergy, kineticToggle_->isChecked());
  energy->setQuantityShown(Quantity::PotentialEnergy, potentialToggle_->isChecked());
  energy->setQuantityShown(Quantity::TotalEnergy, totalToggle_->isChecked());
  TimeChart* residual = charts_[kResidualChart];
  residual->setQuantityShown(Quantity::EnergyResidual, residualShown && !relative);
  residual->setQuantityShown(Quantity::RelativeEnergyResidual, residualShown && relative);
  residual->setValueAxisTitle(relative ? tr("residual / |E₀|") : tr("residual"),
                              relative ? QString() : tr("J"));
  charts_[kDivergenceChart]->setQuantityShown(Quantity::RmsPositionDifference,
                                              divergenceToggle_->isChecked());

  // A chart with nothing to show steps aside and the others share its room.
  for (std::size_t i = 0; i < charts_.size(); ++i) {
    chartsShown_[i] = isChartShown(charts_[i]);
    charts_[i]->setVisible(chartsShown_[i]);
  }
  arrangeCharts();
  viewOutOfDate_ = true;
  refresh();
}

bool ChartPanel::eventFilter(QObject* watched, QEvent* event) {
  if (watched == scroll_->viewport() && event->type() == QEvent::Resize) arrangeCharts();
  return QWidget::eventFilter(watched, event);
}

void ChartPanel::arrangeCharts() {
  std::vector<TimeChart*> shown;
  for (std::size_t i = 0; i < charts_.size(); ++i) {
    if (chartsShown_[i]) shown.push_back(charts_[i]);
  }
  const QSize viewport = scroll_->viewport()->size();
  const int legendHeight = runLegend_->isHidden() ? 0 : runLegend_->sizeHint().height();
  const int columns =
      chartColumns(int(shown.size()), QSize(viewport.width(), viewport.height() - legendHeight));
  if (columns == gridColumns_ && shown == gridCharts_) return;
  gridColumns_ = columns;
  gridCharts_ = shown;
  for (TimeChart* chart : charts_)
    gridLayout_->removeWidget(chart);
  for (int row = 0; row < kChartCount; ++row)
    gridLayout_->setRowStretch(row, 0);
  for (int column = 0; column < kChartCount; ++column)
    gridLayout_->setColumnStretch(column, 0);
  const int count = int(shown.size());
  const int rows = columns > 0 ? (count + columns - 1) / columns : 0;
  for (int i = 0; i < count; ++i) {
    const int row = i / columns;
    const int column = i % columns;
    gridLayout_->addWidget(shown[std::size_t(i)], row, column);
    gridLayout_->setRowStretch(row, 1);
    gridLayout_->setColumnStretch(column, 1);
    // The first row carries the marker labels; each column's lowest chart the time axis' labels
    // and title.
    shown[std::size_t(i)]->setMarkerLabelsShown(row == 0);
    shown[std::size_t(i)]->setTimeAxisLabelsShown(i + columns >= count || row == rows - 1);
  }
}

void ChartPanel::alignPlotAreas() {
  // Every shown chart's plot starts where the widest value labels need it to, and ends where the
  // bottom chart's last time label lets it.
  std::optional<PlotInsets> aligned;
  for (const TimeChart* chart : charts_) {
    const std::optional<PlotInsets> natural = chart->naturalPlotInsets();
    if (!isChartShown(chart) || !natural) continue;
    const PlotInsets widest = aligned.value_or(*natural);
    aligned =
        PlotInsets{std::max(widest.left, natural->left), std::max(widest.right, natural->right)};
  }
  if (!aligned) return;
  for (TimeChart* chart : charts_) {
    const std::optional<PlotInsets> natural = chart->naturalPlotInsets();
    if (!isChartShown(chart) || !natural) continue;
    const PlotInsets extra{aligned->left - natural->left, aligned->right - natural->right};
    const PlotInsets now = chart->extraMargins();
    // Half a pixel of tolerance, so rounding cannot start a relayout loop.
    if (std::abs(extra.left - now.left) >= 0.5 || std::abs(extra.right - now.right) >= 0.5)
      chart->setExtraMargins(extra);
  }
}

void ChartPanel::refresh() {
  redraw();
}

void ChartPanel::redraw() const {
  const double windowSeconds = windowSpin_->value();
  AxisScale timeScale;
  if (!data_.hasSamples()) {
    timeScale = scrollingTimeScale(0.0, 0.0, windowSeconds);
  } else if (wholeRunToggle_->isChecked()) {
    timeScale = growingTimeScale(data_.startTime(), data_.endTime());
  } else {
    timeScale = scrollingTimeScale(data_.startTime(), data_.endTime(), windowSeconds);
  }

  std::array<const SampleHistory*, ChartData::kMaxRuns> histories{};
  const auto runCount = static_cast<std::size_t>(data_.runCount());
  for (std::size_t run = 0; run < runCount; ++run)
    histories[run] = &data_.history(static_cast<int>(run));
  const std::span<const SampleHistory* const> shownHistories(histories.data(), runCount);
  const SampleHistory* baseline =
      data_.baselineShown() ? &data_.history(ChartData::kBaseline) : nullptr;
  for (TimeChart* chart : charts_) {
    if (isChartShown(chart)) chart->redraw(shownHistories, baseline, timeScale);
  }
  viewOutOfDate_ = false;
}

bool ChartPanel::exportPng(const QString& path, const QString& caption) const {
  if (viewOutOfDate_) redraw();
  if (!isVisible()) {
    // A hidden widget gets its pending resize events only when rendered: render one pixel, so
    // the grid places the charts at the panel's size and they size their scenes.
    chartArea_->grab(QRect(0, 0, 1, 1));
  }
  // Each chart lays itself out in posted events, and lining the plot areas up takes another
  // round; both are still pending in a hidden or just-redrawn panel.
  for (int round = 0; round < 3; ++round) {
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
  }

  // The caption above the charts names what they show, so the image explains itself when it is
  // pasted somewhere else; it wraps at the image's width.
  QFont captionFont = font();
  captionFont.setPointSizeF(captionFont.pointSizeF() * 1.1);
  const int width = chartArea_->width();
  const QRect textBounds(kCaptionPadding, kCaptionPadding, width - 2 * kCaptionPadding, 10'000);
  const QRect captionRect =
      QFontMetrics(captionFont).boundingRect(textBounds, Qt::AlignLeft | Qt::TextWordWrap, caption);
  const int captionHeight = caption.isEmpty() ? 0 : captionRect.height() + 2 * kCaptionPadding;

  QImage image(QSize(width, chartArea_->height() + captionHeight) * kExportPixelRatio,
               QImage::Format_ARGB32_Premultiplied);
  image.setDevicePixelRatio(kExportPixelRatio);
  image.fill(chart_colours::kBackground);
  {
    QPainter painter(&image);
    painter.setFont(captionFont);
    painter.setPen(chart_colours::kTitle);
    painter.drawText(textBounds, Qt::AlignLeft | Qt::TextWordWrap, caption);
  }
  chartArea_->render(&image, QPoint(0, captionHeight));
  // The caption as text too, for whoever reads the file's metadata.
  image.setText(QStringLiteral("Description"), caption);
  return image.save(path, "PNG");
}

bool ChartPanel::exportCsv(const QString& path) const {
  return writeChartCsv(path, data_);
}

int ChartPanel::displayedPointCount(int chart, int runIndex) const {
  if (chart < 0 || chart >= kChartCount) return 0;
  return charts_[chart]->pointCount(runIndex);
}

std::size_t ChartPanel::storedSampleCount(int runIndex) const {
  if (runIndex == kBaselineRun) {
    return data_.baselineShown() ? data_.history(ChartData::kBaseline).storedCount() : 0;
  }
  if (runIndex < 0 || runIndex >= data_.runCount()) return 0;
  return data_.history(runIndex).storedCount();
}

QList<QPointF> ChartPanel::displayedPoints(int chart, int runIndex, int curve) const {
  if (chart < 0 || chart >= kChartCount || !isChartShown(charts_[chart])) return {};
  return charts_[chart]->points(runIndex, curve);
}

QPen ChartPanel::displayedPen(int chart, int runIndex, int curve) const {
  if (chart < 0 || chart >= kChartCount) return QPen(Qt::NoPen);
  return charts_[chart]->pen(runIndex, curve);
}

std::pair<double, double> ChartPanel::displayedYRange(int chart) const {
  if (chart < 0 || chart >= kChartCount) return {0.0, 0.0};
  return charts_[chart]->valueRange();
}

QString ChartPanel::displayedValueAxisTitle(int chart) const {
  if (chart < 0 || chart >= kChartCount) return {};
  return charts_[chart]->valueAxisTitle();
}

QStringList ChartPanel::displayedValueTickLabels(int chart) const {
  if (chart < 0 || chart >= kChartCount || !isChartShown(charts_[chart])) return {};
  return charts_[chart]->valueTickLabels();
}

bool ChartPanel::chartShown(int chart) const {
  return chart >= 0 && chart < kChartCount && isChartShown(charts_[chart]);
}

bool ChartPanel::isChartShown(const TimeChart* chart) const {
  return chart->hasCurves() && chart->showsAnyQuantity();
}

QString ChartPanel::runLegendText() const {
  if (runLegend_->isHidden()) return {};
  QTextDocument document;
  document.setHtml(runLegend_->text());
  return document.toPlainText();
}

int ChartPanel::markerCount() const {
  return static_cast<int>(data_.markers().size());
}

QStringList ChartPanel::markerLabels() const {
  QStringList labels;
  for (const ChartMarker& marker : data_.markers())
    labels.append(marker.label);
  return labels;
}

int ChartPanel::displayedMarkerCount() const {
  for (const TimeChart* chart : charts_) {
    if (isChartShown(chart)) return chart->visibleMarkerCount();
  }
  return 0;
}

}  // namespace fooball::gui
