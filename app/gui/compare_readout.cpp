#include "compare_readout.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>
#include <cmath>

#include "charts/chart_panel.h"

namespace fooball::gui {

namespace {

/// Four significant digits, exponent only when the value is very small or very large.
QString figure(double value) {
  const double magnitude = std::abs(value);
  if (magnitude != 0.0 && (magnitude < 1e-3 || magnitude >= 1e5)) {
    return QString::number(value, 'e', 2);
  }
  return QString::number(value, 'g', 4);
}

QString signedFigure(double value) {
  return (value > 0.0 ? QStringLiteral("+") : QString()) + figure(value);
}

}  // namespace

CompareReadout::CompareReadout(QWidget* parent) : QFrame(parent), runs_(new QLabel) {
  setObjectName(QStringLiteral("compareReadout"));
  setStyleSheet(QStringLiteral(
      "#compareReadout { background: #1c1e25; border-bottom: 1px solid #2c303a; }"
      "#compareReadout QLabel { color: #e8eaf0; }"
      "#compareReadout QLabel[role=\"caption\"] { color: #9aa0ae; font-size: 8pt; }"
      "#compareReadout QLabel[role=\"value\"] { font-size: 11pt; font-weight: 600; }"));
  runs_->setTextFormat(Qt::RichText);
  runs_->setToolTip(tr("Both runs start from the same state and get the same forces and edits"));

  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(14, 6, 14, 6);
  layout->setSpacing(22);
  layout->addWidget(runs_);
  layout->addStretch(1);
  rms_ = addTile(tr("RMS position difference"),
                 tr("√(mean over balls of |p_compare − p_main|²): how far the runs have drifted "
                    "apart on average"));
  max_ = addTile(tr("Largest position difference"),
                 tr("The ball whose two copies are furthest apart"));
  energy_ = addTile(tr("Energy difference"),
                    tr("Total energy of the compare run minus the main run's, and relative to "
                       "the main run's"));
  momentum_ = addTile(tr("Momentum difference"), tr("|p_compare − p_main| of the total momenta"));
  showDivergence({});
}

QLabel* CompareReadout::addTile(const QString& caption, const QString& toolTip) {
  auto* tile = new QWidget;
  tile->setToolTip(toolTip);
  auto* tileLayout = new QVBoxLayout(tile);
  tileLayout->setContentsMargins(0, 0, 0, 0);
  tileLayout->setSpacing(0);
  auto* captionLabel = new QLabel(caption);
  captionLabel->setProperty("role", "caption");
  auto* value = new QLabel;
  value->setProperty("role", "value");
  value->setTextInteractionFlags(Qt::TextSelectableByMouse);
  tileLayout->addWidget(captionLabel);
  tileLayout->addWidget(value);
  static_cast<QHBoxLayout*>(layout())->addWidget(tile);
  return value;
}

void CompareReadout::showRuns(const QString& mainBackend, const QString& compareBackend) {
  runs_->setText(
      tr("<span style='font-size:12pt'><span style='color:%1'>●</span> <b>%2</b> "
         "<span style='color:#9aa0ae'>vs</span> <span style='color:%3'>○</span> <b>%4</b></span>")
          .arg(ChartPanel::runColour(0).name(), mainBackend.toHtmlEscaped(),
               ChartPanel::runColour(1).name(), compareBackend.toHtmlEscaped()));
}

void CompareReadout::showDivergence(const Divergence& divergence) {
  rms_->setText(figure(divergence.rmsPositionDifference) + tr(" m"));
  max_->setText(figure(divergence.maxPositionDifference) + tr(" m"));
  energy_->setText(signedFigure(divergence.energyDifference) + tr(" J  (") +
                   signedFigure(100.0 * divergence.relativeEnergyDifference) + tr(" %)"));
  momentum_->setText(figure(divergence.momentumDifference) + tr(" N·s"));
}

QString CompareReadout::text() const {
  return QStringLiteral("RMS %1, max %2, energy %3, momentum %4")
      .arg(rms_->text(), max_->text(), energy_->text(), momentum_->text());
}

}  // namespace fooball::gui
