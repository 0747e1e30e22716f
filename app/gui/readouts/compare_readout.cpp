#include "readouts/compare_readout.h"

#include <QGridLayout>
#include <QLabel>

#include "readouts/readout_cells.h"
#include "run_palette.h"

namespace fooball::gui {

namespace {

QString signedFigure(double value) {
  return (value > 0.0 ? QStringLiteral("+") : QString()) + figure(value);
}

/// " at t = 4.90 s", to the status bar's digits; nothing before the first figures.
QString momentText(const std::optional<double>& time) {
  return time ? CompareReadout::tr(" at t = %1 s").arg(*time, 0, 'f', 2) : QString();
}

}  // namespace

CompareReadout::CompareReadout(QWidget* parent)
    : QFrame(parent), grid_(new QGridLayout(this)), reference_(new QLabel) {
  setObjectName(QStringLiteral("compareReadout"));
  setStyleSheet(
      QStringLiteral("#compareReadout { background: #1c1e25; border-bottom: 1px solid #2c303a; }"
                     "#compareReadout QLabel { color: #e8eaf0; font-size: 9pt; }"
                     "#compareReadout QLabel[role=\"caption\"] { color: #9aa0ae; font-size: 8pt; }"
                     "#compareReadout QLabel[role=\"baseline\"] { color: #9e9e9e; }"));
  // Tight enough that five columns fit beside the settings in a 1000 px window.
  // Tight, so that five columns fit beside the settings in a 1000 px window and five runs'
  // rows leave the box the height.
  grid_->setContentsMargins(8, 2, 8, 2);
  grid_->setHorizontalSpacing(14);
  grid_->setVerticalSpacing(0);

  reference_->setProperty("role", "caption");
  reference_->setTextFormat(Qt::RichText);
  reference_->setToolTip(
      tr("Every run starts from the same state and gets the same forces and edits as run 0: any "
         "difference is the method's"));
  grid_->addWidget(reference_, 0, 0);
  const auto addCaption = [this](int column, const QString& caption, const QString& toolTip) {
    QLabel* label = readoutCell(caption, "caption", toolTip);
    grid_->addWidget(label, 0, column, Qt::AlignRight);
  };
  addCaption(1, tr("RMS Δposition"),
             tr("√(mean over balls of |p_run − p_run 0|²): how far the run has drifted from run 0 "
                "on average"));
  addCaption(2, tr("largest Δposition"), tr("The ball furthest from its copy in run 0"));
  addCaption(3, tr("energy difference"),
             tr("Total energy of the run minus run 0's, and relative to run 0's"));
  addCaption(4, tr("momentum difference"), tr("|P_run − P_run 0| of the total momenta"));
  grid_->setColumnStretch(5, 1);  // the table keeps to the left; the strip's rest is empty
  showRuns({}, false);
}

void CompareReadout::clearRows() {
  for (Row& row : rows_) {
    for (QLabel* label : {row.name, row.rms, row.max, row.energy, row.momentum}) {
      grid_->removeWidget(label);
      delete label;
    }
  }
  rows_.clear();
}

CompareReadout::Row CompareReadout::addRow(int gridRow, const QString& label,
                                           const QString& nameHtml, const QString& toolTip,
                                           const char* role) {
  Row row;
  row.label = label;
  row.name = readoutCell(nameHtml, role, toolTip);
  row.name->setTextFormat(Qt::RichText);
  grid_->addWidget(row.name, gridRow, 0);
  QLabel** figures[] = {&row.rms, &row.max, &row.energy, &row.momentum};
  for (int column = 0; column < 4; ++column) {
    QLabel* value = readoutCell(noFigure(), role, toolTip);
    value->setTextInteractionFlags(Qt::TextSelectableByMouse);
    grid_->addWidget(value, gridRow, column + 1, Qt::AlignRight);
    *figures[column] = value;
  }
  return row;
}

void CompareReadout::showRuns(const QStringList& labels, bool baseline) {
  if (rowsBuilt_ && labels == labels_ && baseline == baselineShown_) return;
  rowsBuilt_ = true;
  labels_ = labels;
  baselineShown_ = baseline;
  clearRows();

  time_.reset();  // the figures read "—" until the next showDivergences()
  showReference();
  const QString referenceLabel = labels.isEmpty() ? QString() : labels.front();
  int gridRow = 1;
  for (int run = 1; run < labels.size(); ++run) {
    const QString html = QStringLiteral("<span style='color:%1'>●</span> %2")
                             .arg(colours::runColour(run).name(), labels[run].toHtmlEscaped());
    const QString toolTip =
        tr("Run %1, %2, against run 0, %3").arg(run).arg(labels[run], referenceLabel);
    rows_.push_back(addRow(gridRow++, labels[run], html, toolTip, "value"));
  }
  if (baseline) {
    const QString toolTip =
        tr("Run 0 with every ball moved 1e-9 m: a run whose divergence stays near this line is as "
           "close to run 0 as chaos allows");
    const QString html = QStringLiteral("<span style='color:%1'>╌</span> %2")
                             .arg(colours::neutralColour().name(), tr("chaos baseline"));
    rows_.push_back(addRow(gridRow++, tr("chaos baseline"), html, toolTip, "baseline"));
  }
}

void CompareReadout::showReference() {
  const QString referenceLabel = labels_.isEmpty() ? QString() : labels_.front();
  reference_->setText(
      tr("difference from <span style='color:%1'>●</span> <b>%2</b> (run 0)%3")
          .arg(colours::runColour(0).name(), referenceLabel.toHtmlEscaped(), momentText(time_)));
}

void CompareReadout::showFigures(Row& row, const std::optional<fooball::Divergence>& divergence) {
  if (!divergence) {
    for (QLabel* label : {row.rms, row.max, row.energy, row.momentum})
      label->setText(noFigure());
    return;
  }
  row.rms->setText(figure(divergence->rmsPositionDifference) + tr(" m"));
  row.max->setText(figure(divergence->maxPositionDifference) + tr(" m"));
  row.energy->setText(signedFigure(divergence->energyDifference) + tr(" J (") +
                      signedFigure(100.0 * divergence->relativeEnergyDifference) + tr(" %)"));
  row.momentum->setText(figure(divergence->momentumDifference) + tr(" N·s"));
}

void CompareReadout::showDivergences(const fooball::GroupDivergences& divergences) {
  const std::vector<fooball::Divergence>& fromRunZero = divergences.fromRunZero;
  time_ = divergences.time;
  showReference();
  const std::size_t runRows = rows_.size() - (baselineShown_ ? 1 : 0);
  for (std::size_t i = 0; i < runRows; ++i) {
    const std::size_t run = i + 1;
    showFigures(rows_[i], run < fromRunZero.size()
                              ? std::optional<fooball::Divergence>(fromRunZero[run])
                              : std::nullopt);
  }
  if (baselineShown_) showFigures(rows_.back(), divergences.baseline);
}

QString CompareReadout::text() const {
  QStringList lines;
  lines.append(tr("difference from %1 (run 0)%2")
                   .arg(labels_.isEmpty() ? QString() : labels_[0], momentText(time_)));
  for (const Row& row : rows_) {
    lines.append(tr("%1: RMS %2, max %3, energy %4, momentum %5")
                     .arg(row.label, row.rms->text(), row.max->text(), row.energy->text(),
                          row.momentum->text()));
  }
  return lines.join(QLatin1Char('\n'));
}

}  // namespace fooball::gui
