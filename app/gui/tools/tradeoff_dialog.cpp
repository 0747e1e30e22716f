#include "tools/tradeoff_dialog.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLineEdit>
#include <QListWidget>
#include <limits>
#include <stdexcept>

#include "fooball/presets.h"
#include "tools/measured_charts.h"
#include "tools/tool_run_panel.h"
#include "tradeoff_chart_builder.h"
#include "widgets/checklist.h"
#include "widgets/view_text.h"

namespace fooball::gui {

namespace {

/// The field's number, or NaN (which checkTradeoffSettings names as bad) when it is none.
double numberIn(const QLineEdit& field) {
  bool isNumber = false;
  const double value = field.text().trimmed().toDouble(&isNumber);
  return isNumber ? value : std::numeric_limits<double>::quiet_NaN();
}

/// How the chart's title names the scene: "'gas' (300 balls)".
QString sceneText(const Scene& scene) {
  return QObject::tr("'%1' (%2 balls)")
      .arg(QString::fromStdString(scene.name))
      .arg(scene.balls.size());
}

}  // namespace

TradeoffDialog::TradeoffDialog(QWidget* parent)
    : ToolDialog(tr("Press Start: CPU cost against trajectory error and against energy error "
                    "appear here, one point per setting"),
                 parent) {
  setObjectName(QStringLiteral("tradeoffDialog"));
  setWindowTitle(tr("Speed vs accuracy"));
  connect(charts(), &MeasuredCharts::measurementClicked, this, [this](std::size_t index) {
    const measure::TradeoffPoint& point = points_.at(index);
    emit openRequested(
        {scene_, presetName_, presetName_, RunSpec{point.setting.backend, point.setting.options}});
  });
  layOut(tr("What each backend's settings cost in CPU time and get wrong on a scene, the same "
            "measurement as <tt>fooball-cli tradeoff</tt>: every setting runs the scene, and its "
            "balls are compared with the %1 backend's. <b>The simulation in the main window is "
            "paused while it runs.</b> Click a point to open that setting on the scene.")
             .arg(fromView(measure::kReferenceBackend)),
         createSettings(), nullptr);
  resize(1000, 760);
}

QWidget* TradeoffDialog::createSettings() {
  auto* settings = new QWidget;
  auto* form = new QFormLayout(settings);
  form->setContentsMargins(0, 0, 0, 0);
  preset_ = new QComboBox;
  for (const Preset& preset : presets())
    preset_->addItem(fromView(preset.name));
  preset_->setCurrentText(QStringLiteral("gas"));
  preset_->setToolTip(tr("The built-in scene every setting runs"));
  form->addRow(tr("&Scene:"), preset_);
  backends_ = newBackendChecklist(
      tr("The backends to measure: each at its defaults, or at 1 to 64 substeps (and 2, 8, 32 "
         "iterations) when it has them"));
  form->addRow(tr("&Backends:"), backends_);
  const measure::TradeoffSettings defaults;
  duration_ = new QLineEdit(QString::number(defaults.duration));
  duration_->setToolTip(
      tr("Simulated seconds each setting runs (cost, energy, momentum, overlap)"));
  form->addRow(tr("&Duration (s):"), duration_);
  compareAt_ = new QLineEdit(QString::number(defaults.compareAt));
  compareAt_->setToolTip(tr("Simulated second at which the balls are compared with the %1 "
                            "backend's")
                             .arg(fromView(measure::kReferenceBackend)));
  form->addRow(tr("Compare &at (s):"), compareAt_);
  return settings;
}

bool TradeoffDialog::start() {
  if (runPanel()->running()) return false;
  measure::TradeoffSettings settings;
  settings.duration = numberIn(*duration_);
  settings.compareAt = numberIn(*compareAt_);
  std::vector<measure::TradeoffSetting> grid;
  Scene scene;
  try {
    const std::vector<BackendInfo> chosen = checkedBackends(*backends_);
    if (chosen.empty()) throw std::invalid_argument("backends: check at least one");
    grid = measure::tradeoffGrid(chosen);
    scene = loadPreset(preset_->currentText().toStdString());
    measure::checkTradeoffSettings(settings);
  } catch (const std::exception& problem) {
    runPanel()->showError(QString::fromStdString(problem.what()));
    return false;
  }
  points_.clear();
  charts()->showCharts({}, {});
  const QString presetName = preset_->currentText();
  const QString starting = tr("Measuring %1 settings on %2").arg(grid.size()).arg(sceneText(scene));
  return runPanel()->start(
      [this, scene, presetName, grid, settings](std::stop_token stop,
                                                const ToolRunPanel::Report& report) {
        const auto progress = [&](const measure::TradeoffProgress& at) {
          report(at.fraction, tr("%1 %2 measured")
                                  .arg(QString::fromStdString(at.setting->backend),
                                       QString::fromStdString(measure::settingsText(*at.setting))));
        };
        std::vector<measure::TradeoffPoint> points =
            measure::measureTradeoff(scene, grid, settings, progress, stop);
        return [this, scene, presetName, settings, points = std::move(points)]() mutable {
          presetName_ = presetName;
          showPoints(scene, settings, std::move(points));
        };
      },
      starting);
}

void TradeoffDialog::showPoints(const Scene& scene, const measure::TradeoffSettings& settings,
                                std::vector<measure::TradeoffPoint> points) {
  scene_ = scene;
  points_ = std::move(points);
  charts()->showCharts(plots::makeTradeoffCharts(points_, settings),
                       plots::tradeoffChartTitle(sceneText(scene_).toStdString(), settings));
}

void TradeoffDialog::setSettingsEnabled(bool enabled) {
  preset_->setEnabled(enabled);
  backends_->setEnabled(enabled);
  duration_->setEnabled(enabled);
  compareAt_->setEnabled(enabled);
}

}  // namespace fooball::gui
