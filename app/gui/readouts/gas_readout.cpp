#include "readouts/gas_readout.h"

#include <QGridLayout>
#include <QLabel>
#include <QVBoxLayout>
#include <cmath>

#include "readouts/readout_cells.h"
#include "run_palette.h"

namespace fooball::gui {

namespace {

constexpr int kHeaderRow = 0;
constexpr int kFirstFigureRow = 1;
/// KS distance that N independent speeds from the distribution stay below 95% of the time,
/// times √N (Kolmogorov's asymptotic quantile).
constexpr double kKolmogorov95 = 1.358;

const QString kNotApplicable = QStringLiteral("n/a");

QString ratio(double measured, double theory) {
  return theory > 0.0 ? QString::number(measured / theory, 'f', 3) : noFigure();
}

/// The theory's rows differ for balls of one size and of several.
QString hendersonToolTip(bool equalSizes) {
  const QString model = equalSizes
                            ? QObject::tr(
                                  "Henderson's equation of state for hard disks, Z = (1 + η²/8) / "
                                  "(1 − η)²")
                            : QObject::tr(
                                  "Balls of several sizes: the Santos–Yuste–López de Haro mixture "
                                  "mapping of Henderson's equation of state");
  return model + QObject::tr(
                     ", P = Z·N·kT / A: what an equilibrium gas of these balls at this "
                     "kT and packing fraction presses on its walls. A finite box reads a "
                     "little higher (about 1% here), as the walls order the balls next "
                     "to them.");
}

QStringList caveatNames(const TheoryCaveats& caveats) {
  QStringList names;
  if (caveats.gravity) names << QObject::tr("gravity");
  if (caveats.drag) names << QObject::tr("air resistance");
  if (caveats.noBallCollisions) names << QObject::tr("ball collisions off");
  if (caveats.openWalls) names << QObject::tr("a wall off");
  if (caveats.attractors) names << QObject::tr("attractors");
  return names;
}

}  // namespace

GasReadout::GasReadout(QWidget* parent)
    : QFrame(parent), grid_(new QGridLayout), summary_(new QLabel), caveat_(new QLabel) {
  setObjectName(QStringLiteral("gasReadout"));
  setStyleSheet(
      QStringLiteral("#gasReadout { background: #16171c; }"
                     "#gasReadout QLabel { color: #e8eaf0; font-size: 9pt; }"
                     "#gasReadout QLabel[role=\"caption\"] { color: #9aa0ae; font-size: 8pt; }"
                     "#gasReadout QLabel[role=\"theory\"] { color: #b4b7c0; }"
                     "#gasReadout QLabel[role=\"caveat\"] { color: #ffb74d; font-size: 8pt; }"));
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(8, 4, 8, 4);
  layout->setSpacing(2);
  summary_->setProperty("role", "caption");
  layout->addWidget(summary_);
  caveat_->setProperty("role", "caveat");
  caveat_->setWordWrap(true);
  caveat_->hide();
  layout->addWidget(caveat_);
  layout->addLayout(grid_);
  layout->addStretch(1);  // the table keeps to the top
  grid_->setContentsMargins(0, 0, 0, 0);
  grid_->setHorizontalSpacing(14);
  grid_->setVerticalSpacing(0);

  const auto caption = [this](Row row, const QString& text, const QString& toolTip) {
    captions_[row] = readoutCell(text, "caption", toolTip);
    grid_->addWidget(captions_[row], kFirstFigureRow + row, 0);
  };
  caption(kTemperature, tr("kinetic temperature kT (J per ball)"),
          tr("⟨½ m v²⟩ over the balls: the mean kinetic energy per ball. A ball in the plane has "
             "two degrees of freedom, each holding ½ kT at equilibrium."));
  caption(kDistance, tr("KS distance from Maxwell–Boltzmann"),
          tr("Kolmogorov–Smirnov distance: the largest gap between the distribution function of "
             "the balls' speeds and 2D Maxwell–Boltzmann's at the run's own kT (0: a perfect "
             "match). A gas that starts far from it and reaches it has thermalised."));
  caption(kPressure, tr("wall pressure (N/m)"), {});
  caption(kHendersonPressure, tr("   Henderson's (N/m)"), hendersonToolTip(true));
  caption(kPressureRatio, tr("   measured / Henderson"),
          tr("1 for an equilibrium hard-disk gas (about 1.01 in a finite box)"));
  caption(kCollisionRate, tr("collision rate (1/s per ball)"), {});
  caption(kEnskogRate, tr("   Enskog's (1/s per ball)"),
          tr("Enskog's rate: ν = n · 2σ · √(π kT / 2μ) · χ(η), with n the number density, σ the "
             "contact distance, μ the reduced mass and χ Henderson's contact value: what an "
             "equilibrium hard-disk gas at this kT and packing fraction does."));
  caption(kRateRatio, tr("   measured / Enskog"), tr("1 for an equilibrium hard-disk gas"));
  showRuns({});
}

void GasReadout::showRuns(const QStringList& labels) {
  if (columnsBuilt_ && labels == labels_) return;
  columnsBuilt_ = true;
  labels_ = labels;
  for (QLabel* header : headers_)
    delete header;
  headers_.clear();
  for (const Column& column : columns_) {
    for (QLabel* label : column)
      delete label;
  }
  columns_.clear();

  for (int run = 0; run < labels.size(); ++run) {
    const QString html = QStringLiteral("<span style='color:%1'>●</span> %2")
                             .arg(colours::runColour(run).name(), labels[run].toHtmlEscaped());
    QLabel* header = readoutCell(html, "value", tr("Run %1: %2").arg(run).arg(labels[run]));
    header->setTextFormat(Qt::RichText);
    grid_->addWidget(header, kHeaderRow, run + 1, Qt::AlignRight);
    headers_.push_back(header);
    Column column{};
    for (int row = 0; row < kRowCount; ++row) {
      const bool theory = row == kHendersonPressure || row == kPressureRatio ||
                          row == kEnskogRate || row == kRateRatio;
      column[row] = readoutCell(noFigure(), theory ? "theory" : "value", captions_[row]->toolTip());
      column[row]->setTextInteractionFlags(Qt::TextSelectableByMouse);
      grid_->addWidget(column[row], kFirstFigureRow + row, run + 1, Qt::AlignRight);
    }
    columns_.push_back(column);
  }
}

void GasReadout::showStatistics(const GasMonitor::Snapshot& snapshot) {
  if (snapshot.runs.empty()) return;
  const RunGasStatistics& reference = snapshot.runs.front();
  const double window = reference.windowSpan;  // s, the same for every run: they step together
  summary_->setText(tr("packing fraction η = %1 · %2 balls")
                        .arg(reference.theory.packingFraction, 0, 'f', 3)
                        .arg(reference.balls));
  captions_[kPressure]->setText(tr("wall pressure, last %1 s (N/m)").arg(window, 0, 'f', 1));
  captions_[kCollisionRate]->setText(
      tr("collision rate, last %1 s (1/s per ball)").arg(window, 0, 'f', 1));
  const QString measuredOver = tr(" over the last %1 s of simulated time (up to %2 s).")
                                   .arg(window, 0, 'f', 1)
                                   .arg(GasMonitor::kDefaultWindowSeconds, 0, 'f', 0);
  captions_[kPressure]->setToolTip(
      tr("The impulse the walls take per second per metre of wall (2D pressure, N/m),") +
      measuredOver);
  captions_[kCollisionRate]->setToolTip(
      tr("Ball–ball collisions per ball per second (each collision counts for both balls),") +
      measuredOver);
  captions_[kHendersonPressure]->setToolTip(hendersonToolTip(reference.theory.equalSizes));
  captions_[kHendersonPressure]->setText(reference.theory.equalSizes
                                             ? tr("   Henderson's (N/m)")
                                             : tr("   Henderson–SYL mixture (N/m)"));
  const QStringList caveats = caveatNames(snapshot.caveats);
  caveat_->setVisible(!caveats.isEmpty());
  caveat_->setText(caveats.isEmpty() ? QString()
                                     : tr("The theory is for an equilibrium gas in a closed box, "
                                          "so it does not apply here (%1).")
                                           .arg(caveats.join(QStringLiteral(", "))));

  const double critical =
      reference.balls > 0 ? kKolmogorov95 / std::sqrt(double(reference.balls)) : 0.0;
  captions_[kDistance]->setText(
      tr("KS distance from Maxwell–Boltzmann (eq. < %1)").arg(critical, 0, 'f', 3));

  for (std::size_t run = 0; run < columns_.size() && run < snapshot.runs.size(); ++run) {
    const RunGasStatistics& gas = snapshot.runs[run];
    Column& column = columns_[run];
    const bool measured = gas.windowSpan > 0.0;
    const bool theory = !snapshot.caveats.any();
    column[kTemperature]->setText(figure(gas.kineticTemperature));
    column[kDistance]->setText(QString::number(gas.maxwellBoltzmannDistance, 'f', 3));
    column[kPressure]->setText(measured ? figure(gas.wallPressure) : noFigure());
    column[kCollisionRate]->setText(measured ? figure(gas.collisionRate) : noFigure());
    column[kHendersonPressure]->setText(theory ? figure(gas.theory.pressure) : kNotApplicable);
    column[kEnskogRate]->setText(theory ? figure(gas.theory.collisionRate) : kNotApplicable);
    column[kPressureRatio]->setText(
        !theory ? kNotApplicable
                : (measured ? ratio(gas.wallPressure, gas.theory.pressure) : noFigure()));
    column[kRateRatio]->setText(
        !theory ? kNotApplicable
                : (measured ? ratio(gas.collisionRate, gas.theory.collisionRate) : noFigure()));
  }
}

QString GasReadout::text(Row row, int run) const {
  return columns_.at(static_cast<std::size_t>(run))[row]->text();
}

QString GasReadout::summary() const {
  return summary_->text();
}

QString GasReadout::caveat() const {
  return caveat_->text();
}

}  // namespace fooball::gui
