#include "chart_panel.h"

#include <QChart>
#include <QComboBox>
#include <QCoreApplication>
#include <QLabel>
#include <QListView>
#include <QPalette>
#include <QResizeEvent>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <vector>

#include "chart_csv.h"
#include "chart_grid.h"
#include "chart_png.h"
#include "chart_style.h"
#include "chart_toolbar.h"
#include "run_palette.h"
#include "time_chart.h"

namespace fooball::gui {
namespace {

/// ms between redraws while samples come in: 10 per second looks live, and a redraw of all
/// curves costs a few ms of the GUI thread the simulation also runs on.
constexpr int kRefreshIntervalMs = 100;

}  // namespace

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

  // The charts share the panel in a grid (arrangeCharts) rather than a splitter: a column beside
  // the box stacks them, a wide floating dock fits them side by side.
  chartGrid_ = new ChartGrid(this);
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

  // Which chart leads when not all fit: the panel shows whole charts only, as many as fit, and
  // this selector reaches the others.
  selector_ = new QComboBox;
  selector_->setObjectName(QStringLiteral("chartSelector"));
  selector_->addItems({tr("Momentum"), tr("Energy"), tr("Residual"), tr("Divergence")});
  selector_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
  selector_->setToolTip(tr("The chart shown first: the panel shows as many whole charts as fit"));
  selector_->hide();
  connect(selector_, &QComboBox::currentIndexChanged, this, &ChartPanel::arrangeCharts);

  chartArea_ = new QWidget(this);
  chartArea_->setPalette(chartPalette);
  chartArea_->setAutoFillBackground(true);
  auto* chartLayout = new QVBoxLayout(chartArea_);
  chartLayout->setContentsMargins(0, 0, 0, 0);
  chartLayout->setSpacing(0);
  chartLayout->addWidget(runLegend_);
  chartLayout->addWidget(selector_, 0, Qt::AlignLeft);
  chartLayout->addWidget(chartGrid_, 1);

  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(0);
  toolBar_ = new ChartToolBar(this);
  connect(toolBar_, &ChartToolBar::wholeRunToggled, this, &ChartPanel::setShowWholeRun);
  connect(toolBar_, &ChartToolBar::windowSecondsChanged, this, &ChartPanel::setWindowSeconds);
  connect(toolBar_, &ChartToolBar::shownChanged, this, &ChartPanel::applyToggles);
  layout->addWidget(toolBar_);
  // No scrolling: a chart cut by the panel's edge showed a strip of plot without its time axis.
  chartArea_->installEventFilter(this);
  layout->addWidget(chartArea_, 1);

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
  toolBar_->setWindowSeconds(seconds);
  viewOutOfDate_ = true;
  refresh();
}

void ChartPanel::setShowWholeRun(bool whole) {
  toolBar_->setWholeRun(whole);
  for (TimeChart* chart : charts_)
    chart->forgetValueScale();
  viewOutOfDate_ = true;
  refresh();
}

void ChartPanel::applyToggles() {
  const ChartToolBar::Shown shown = toolBar_->shown();
  const bool residualShown = shown.residual;
  const bool relative = shown.relativeResidual;

  TimeChart* momentum = charts_[kMomentumChart];
  momentum->setQuantityShown(Quantity::MomentumX, shown.momentumX);
  momentum->setQuantityShown(Quantity::MomentumY, shown.momentumY);
  momentum->setQuantityShown(Quantity::MomentumMagnitude, shown.momentumMagnitude);
  TimeChart* energy = charts_[kEnergyChart];
  energy->setQuantityShown(Quantity::KineticEnergy, shown.kinetic);
  energy->setQuantityShown(Quantity::PotentialEnergy, shown.potential);
  energy->setQuantityShown(Quantity::TotalEnergy, shown.total);
  TimeChart* residual = charts_[kResidualChart];
  residual->setQuantityShown(Quantity::EnergyResidual, residualShown && !relative);
  residual->setQuantityShown(Quantity::RelativeEnergyResidual, residualShown && relative);
  residual->setValueAxisTitle(relative ? tr("residual / |E₀|") : tr("residual"),
                              relative ? QString() : tr("J"));
  charts_[kDivergenceChart]->setQuantityShown(Quantity::RmsPositionDifference, shown.divergence);

  // A chart with nothing to show steps aside and the others share its room.
  arrangeCharts();
  viewOutOfDate_ = true;
  refresh();
}

bool ChartPanel::eventFilter(QObject* watched, QEvent* event) {
  if (watched == chartArea_ && event->type() == QEvent::Resize) arrangeCharts();
  return QWidget::eventFilter(watched, event);
}

void ChartPanel::arrangeCharts() {
  const std::vector<TimeChart*> on = shownCharts();
  for (int chart = 0; chart < kChartCount; ++chart)
    static_cast<QListView*>(selector_->view())
        ->setRowHidden(chart, !isChartShown(charts_[std::size_t(chart)]));
  const int legendHeight = runLegend_->isHidden() ? 0 : runLegend_->heightForWidth(width());
  const QSize whole(chartArea_->width(), chartArea_->height() - legendHeight);
  int chartHeight = 0;
  for (const TimeChart* chart : on)
    chartHeight = std::max(chartHeight, chart->minimumHeight());
  const int count = int(on.size());
  int fit = chartsThatFit(count, whole, chartHeight);
  if (fit < count) {
    fit = chartsThatFit(count, whole - QSize(0, selector_->sizeHint().height()), chartHeight);
  }
  selector_->setVisible(fit < count);
  // The selected chart first, then the ones after it (round to the first) as far as room goes.
  const auto selected =
      std::find(on.begin(), on.end(), charts_[std::size_t(std::max(selector_->currentIndex(), 0))]);
  const std::size_t first =
      fit < count && selected != on.end() ? std::size_t(selected - on.begin()) : 0;
  std::vector<TimeChart*> placed;
  for (std::size_t i = 0; i < std::min(std::size_t(fit), on.size()); ++i)
    placed.push_back(on[(first + i) % on.size()]);
  for (TimeChart* chart : charts_) {
    if (std::find(placed.begin(), placed.end(), chart) == placed.end()) chart->hide();
  }
  chartGrid_->arrange(placed, whole);
}

void ChartPanel::alignPlotAreas() {
  gui::alignPlotAreas(shownCharts());
}

std::vector<TimeChart*> ChartPanel::shownCharts() const {
  std::vector<TimeChart*> shown;
  for (TimeChart* chart : charts_) {
    if (isChartShown(chart)) shown.push_back(chart);
  }
  return shown;
}

void ChartPanel::refresh() {
  redraw();
}

void ChartPanel::redraw() const {
  const double windowSeconds = toolBar_->windowSeconds();
  AxisScale timeScale;
  if (!data_.hasSamples()) {
    timeScale = scrollingTimeScale(0.0, 0.0, windowSeconds);
  } else if (toolBar_->wholeRun()) {
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

  return writeChartPng(path, *chartArea_, caption);
}

bool ChartPanel::exportCsv(const QString& path) const {
  return writeChartCsv(path, data_);
}

bool ChartPanel::chartShown(int chart) const {
  return chart >= 0 && chart < kChartCount && isChartShown(charts_[chart]);
}

bool ChartPanel::isChartShown(const TimeChart* chart) const {
  return chart->hasCurves() && chart->showsAnyQuantity();
}

}  // namespace fooball::gui
