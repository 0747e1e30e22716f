#include "readouts/run_counters.h"

#include <QGridLayout>
#include <QLabel>
#include <QLocale>
#include <cmath>
#include <cstdint>

#include "readouts/readout_cells.h"
#include "run_palette.h"
#include "widgets/number_format.h"

namespace fooball::gui {

namespace {

// The widest figure each column keeps room for, so the sidebar (fitted to its controls) keeps
// its width as the counts grow, up to 100 million collisions (a minute of 100,000 balls), every
// ball of the largest scene out, an overlap of a whole radius and more.
constexpr std::uint64_t kWidestCollisions = 99'999'999;
constexpr std::uint64_t kWidestEscaped = 1'000'000;  // the app's ball limit
const QString kWidestOverlap = QStringLiteral("<0.01 %");

QLabel* rightAligned(const QString& text, const QString& toolTip) {
  auto* label = new QLabel(text);
  label->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
  label->setToolTip(toolTip);
  return label;
}

/// A figure's cell, as wide as `widest` at any count.
QLabel* figureCell(const QString& widest) {
  QLabel* label = rightAligned(noFigure(), QString());
  label->setMinimumWidth(label->fontMetrics().horizontalAdvance(widest));
  return label;
}

/// A run spec that may wrap after each ':', ',' and '=' (zero-width spaces): specs have no
/// spaces, and the sidebar is narrower than the longest.
QString wrappable(const QString& spec) {
  QString text = spec.toHtmlEscaped();
  for (const QChar separator : {QLatin1Char(':'), QLatin1Char(','), QLatin1Char('=')})
    text.replace(separator, QString(separator) + QChar(0x200B));
  return text;
}

/// An overlap as a percentage of the smaller radius: "0", "<0.01 %" (rounding-level contacts),
/// "0.31 %", "12 %", "133 %". Whole percents from 10 % up: two significant digits would write
/// an overlap deeper than the radius, which a method beyond its limits reaches, as "1.3e+02".
QString overlapText(double fraction) {
  if (!(fraction > 0.0)) return QStringLiteral("0");
  if (fraction < 1e-4) return QStringLiteral("<0.01 %");
  const double percent = 100.0 * fraction;
  if (percent < 9.95) return QLocale().toString(percent, 'g', 2) + QStringLiteral(" %");
  return QLocale().toString(std::round(percent), 'f', 0) + QStringLiteral(" %");
}

}  // namespace

RunCounters::RunCounters(QWidget* parent)
    : QGroupBox(tr("Counters"), parent), grid_(new QGridLayout(this)) {
  setObjectName(QStringLiteral("runCounters"));
  setToolTip(tr("Since the scene was loaded or restarted, per run: what fooball-cli run reports"));
  grid_->setHorizontalSpacing(3);
  grid_->setVerticalSpacing(2);
  const QStringList headers{tr("ball–ball"), tr("wall"), tr("overlap"), tr("out")};
  const QStringList toolTips{
      tr("Ball–ball collisions: impulses exchanged between two balls"), tr("Wall bounces"),
      tr("Deepest overlap now, ball–ball or ball–wall, as a percentage of the smaller radius: "
         "how far the method lets balls sink into each other"),
      tr("Escaped: balls whose centre is outside the box now")};
  for (int column = 0; column < headers.size(); ++column)
    grid_->addWidget(
        rightAligned(QStringLiteral("<b>%1</b>").arg(headers[column]), toolTips[column]), 0,
        column);
}

void RunCounters::showRuns(const QStringList& labels) {
  if (labels == labels_ && !rows_.empty()) return;
  labels_ = labels;
  for (const Row& row : rows_) {
    for (QLabel* cell :
         {row.name, row.ballCollisions, row.wallCollisions, row.overlap, row.escaped})
      delete cell;
  }
  rows_.clear();
  for (int run = 0; run < labels.size(); ++run) {
    // Each run's spec whole on a line of its own (wrapped if long), its figures under it.
    const QString nameHtml = QStringLiteral("<span style='color:%1'>●</span> %2")
                                 .arg(colours::runColour(run).name(), wrappable(labels[run]));
    Row row{labels[run],
            nameHtml,
            0,
            new QLabel(nameHtml),
            figureCell(formatCount(kWidestCollisions)),
            figureCell(formatCount(kWidestCollisions)),
            figureCell(kWidestOverlap),
            figureCell(formatCount(kWidestEscaped))};
    row.name->setObjectName(QStringLiteral("runCounterName"));
    row.name->setWordWrap(true);
    row.name->setToolTip(tr("Run %1: %2").arg(run).arg(labels[run]));
    const int line = 2 * run + 1;
    grid_->addWidget(row.name, line, 0, 1, 4);
    int column = 0;
    for (QLabel* cell : {row.ballCollisions, row.wallCollisions, row.overlap, row.escaped})
      grid_->addWidget(cell, line + 1, column++);
    rows_.push_back(row);
  }
}

void RunCounters::showMetrics(const std::vector<Metrics>& metrics) {
  for (std::size_t run = 0; run < rows_.size(); ++run) {
    Row& row = rows_[run];
    if (run >= metrics.size()) {
      for (QLabel* cell : {row.ballCollisions, row.wallCollisions, row.overlap, row.escaped})
        cell->setText(noFigure());
      continue;
    }
    const Metrics& m = metrics[run];
    row.ballCollisions->setText(formatCount(m.ballCollisions));
    row.wallCollisions->setText(formatCount(m.wallCollisions));
    row.overlap->setText(overlapText(m.maxOverlap));
    row.escaped->setText(formatCount(m.escaped));
    if (m.restingBalls != row.resting) {
      row.resting = m.restingBalls;
      row.name->setText(row.resting == 0
                            ? row.nameHtml
                            : tr("%1 · %2 resting").arg(row.nameHtml, formatCount(row.resting)));
    }
  }
}

QString RunCounters::text() const {
  QStringList lines;
  for (const Row& row : rows_) {
    QString line = tr("%1: %2 ball–ball, %3 wall, overlap %4, %5 escaped")
                       .arg(row.label, row.ballCollisions->text(), row.wallCollisions->text(),
                            row.overlap->text(), row.escaped->text());
    if (row.resting != 0) line += tr(", %1 resting").arg(formatCount(row.resting));
    lines.append(line);
  }
  return lines.join(QLatin1Char('\n'));
}

}  // namespace fooball::gui
