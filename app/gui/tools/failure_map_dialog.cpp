#include "tools/failure_map_dialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>

#include "failure_map_chart_builder.h"
#include "tools/measured_charts.h"
#include "tools/tool_run_panel.h"
#include "widgets/checklist.h"
#include "widgets/view_text.h"

namespace fooball::gui {

using failure_map::SweepPoint;
using failure_map::SweepSpec;

FailureMapDialog::FailureMapDialog(QWidget* parent)
    : ToolDialog(tr("Press Start: each sweep's error against its parameter appears here, one "
                    "line per backend, the failing points ringed"),
                 parent) {
  setObjectName(QStringLiteral("failureMapDialog"));
  setWindowTitle(tr("Failure map"));
  connect(charts(), &MeasuredCharts::measurementClicked, this, [this](std::size_t index) {
    const SweepPoint& point = shown_.at(index);
    emit openRequested({point.scene, QString(),
                        tr("%1 sweep at %2 (%3)")
                            .arg(QString::fromStdString(point.sweep))
                            .arg(point.parameter, 0, 'g', 3)
                            .arg(QString::fromStdString(point.variant)),
                        RunSpec{point.backend, {}}});
  });

  shownSweep_ = new QComboBox;
  shownSweep_->setToolTip(tr("The sweep the charts show"));
  shownSweep_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
  connect(shownSweep_, &QComboBox::currentTextChanged, this, &FailureMapDialog::showSweep);
  auto* shownLabel = new QLabel(tr("S&weep shown:"));
  shownLabel->setBuddy(shownSweep_);
  auto* bottom = new QHBoxLayout;
  bottom->addWidget(shownLabel);
  bottom->addWidget(shownSweep_);

  layOut(tr("Where each method starts to fail: every sweep runs a family of scenes, harder and "
            "harder, on each backend at its defaults and judges each against a limit, the same "
            "sweeps as <tt>fooball-cli failure-map</tt>. <b>The simulation in the main window is "
            "paused while it runs.</b> Click a point to open that scene."),
         createSettings(), bottom);
  resize(1100, 800);
}

QWidget* FailureMapDialog::createSettings() {
  auto* settings = new QWidget;
  auto* form = new QFormLayout(settings);
  form->setContentsMargins(0, 0, 0, 0);
  QStringList names;
  QStringList titles;
  for (const SweepSpec& spec : failure_map::sweepSpecs()) {
    names.append(fromView(spec.name));
    titles.append(fromView(spec.title));
  }
  sweeps_ = newChecklist(names, titles, tr("The sweeps to run, one after another"));
  backends_ = newBackendChecklist(tr("The backends each sweep runs on, at their defaults"));
  // Side by side: the charts need the height.
  auto* lists = new QHBoxLayout;
  lists->addWidget(sweeps_);
  lists->addWidget(backends_);
  form->addRow(tr("Sweeps and backends:"), lists);
  quick_ = new QCheckBox(tr("&Quick: coarser grids and shorter scenes"));
  quick_->setChecked(true);
  quick_->setToolTip(tr("As failure-map --quick: seconds instead of minutes"));
  form->addRow(QString(), quick_);
  return settings;
}

bool FailureMapDialog::start() {
  if (runPanel()->running()) return false;
  std::vector<const SweepSpec*> sweeps;
  for (const QString& name : checkedNames(*sweeps_))
    sweeps.push_back(&failure_map::findSweep(name.toStdString()));
  const std::vector<BackendInfo> backends = checkedBackends(*backends_);
  if (sweeps.empty() || backends.empty()) {
    runPanel()->showError(sweeps.empty() ? tr("sweeps: check at least one")
                                         : tr("backends: check at least one"));
    return false;
  }
  points_.clear();
  shown_.clear();
  shownSweep_->clear();
  charts()->showCharts({}, {});
  const bool quick = quick_->isChecked();
  const QString starting =
      tr("Starting %1 on %2").arg(fromView(sweeps.front()->name), fromView(backends.front().name));
  return runPanel()->start(
      [this, sweeps, backends, quick](std::stop_token stop, const ToolRunPanel::Report& report) {
        const auto progress = [&](const failure_map::FailureMapProgress& at) {
          report(at.fraction, tr("%1 on %2").arg(fromView(at.sweep->name), fromView(at.backend)));
        };
        std::vector<SweepPoint> points =
            failure_map::runFailureMap(sweeps, backends, quick, progress, stop);
        return [this, points = std::move(points)]() mutable { showPoints(std::move(points)); };
      },
      starting);
}

void FailureMapDialog::showPoints(std::vector<SweepPoint> points) {
  points_ = std::move(points);
  QStringList swept;
  for (const SweepPoint& point : points_) {
    const QString name = QString::fromStdString(point.sweep);
    if (!swept.contains(name)) swept.append(name);
  }
  shownSweep_->addItems(swept);  // shows the first
}

void FailureMapDialog::showSweep(const QString& name) {
  shown_.clear();
  if (name.isEmpty()) return;
  for (const SweepPoint& point : points_) {
    if (point.sweep == name.toStdString()) shown_.push_back(point);
  }
  const SweepSpec& spec = failure_map::findSweep(name.toStdString());
  charts()->showCharts(plots::makeFailureMapCharts(spec, shown_),
                       plots::failureMapChartTitle(spec));
}

void FailureMapDialog::setSettingsEnabled(bool enabled) {
  sweeps_->setEnabled(enabled);
  backends_->setEnabled(enabled);
  quick_->setEnabled(enabled);
  shownSweep_->setEnabled(enabled);
}

}  // namespace fooball::gui
