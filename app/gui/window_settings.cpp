#include "window_settings.h"

#include <QAction>
#include <QSettings>
#include <algorithm>

#include "frame_loop.h"
#include "main_window.h"
#include "run_controller.h"
#include "simulation_view.h"
#include "window_actions.h"

namespace fooball::gui {

namespace {

constexpr double kMinTimeScale = 0.05;
constexpr double kMaxTimeScale = 8.0;

}  // namespace

bool readWindowSettings(MainWindow& window) {
  QSettings settings;
  window.restoreGeometry(settings.value("window/geometry").toByteArray());
  const bool restored = window.restoreState(settings.value("window/state").toByteArray());
  const WindowActions& actions = window.actions();
  actions.temperature()->setChecked(settings.value("drawing/temperature", false).toBool());
  actions.tethers()->setChecked(settings.value("drawing/tethers", true).toBool());
  actions.velocityVectors()->setChecked(settings.value("drawing/velocityVectors", false).toBool());
  actions.centreOfMass()->setChecked(settings.value("drawing/centreOfMass", false).toBool());
  const bool sideBySide = settings.value("drawing/sideBySide", false).toBool();
  (sideBySide ? actions.sideBySide() : actions.overlay())->trigger();
  const auto mode = static_cast<MouseMode>(
      std::clamp(settings.value("mouse/mode", 0).toInt(), 0, int(MouseMode::Slingshot)));
  const auto scope = static_cast<Scope>(
      std::clamp(settings.value("mouse/scope", 0).toInt(), 0, int(Scope::Selected)));
  const double strength =
      std::max(0.0, settings.value("mouse/strength", Interactions::kDefaultStrength).toDouble());
  window.runs().changeTools([&](RunGroup& group) {
    group.setMouseMode(mode);
    group.setScope(scope);
    group.setStrength(strength);
  });
  window.frames().setTimeScale(
      std::clamp(settings.value("time/scale", FrameLoop::kDefaultTimeScale).toDouble(),
                 kMinTimeScale, kMaxTimeScale));
  return restored;
}

void writeWindowSettings(const MainWindow& window) {
  QSettings settings;
  const SimulationView& view = *window.view();
  const RunGroup& group = window.runs().group();
  settings.setValue("window/geometry", window.saveGeometry());
  settings.setValue("window/state", window.saveState());
  settings.setValue("drawing/temperature", view.temperatureColouring());
  settings.setValue("drawing/tethers", view.tethers());
  settings.setValue("drawing/velocityVectors", view.velocityVectors());
  settings.setValue("drawing/centreOfMass", view.centreOfMass());
  settings.setValue("drawing/sideBySide", view.compareLayout() == CompareLayout::SideBySide);
  settings.setValue("mouse/mode", int(group.interactions().mode));
  settings.setValue("mouse/scope", int(group.interactions().scope));
  settings.setValue("mouse/strength", group.interactions().strength);
  settings.setValue("time/scale", window.frames().timeScale());
  settings.setValue("run/backend", QString::fromStdString(group.spec(0).backend));
  const QString preset = window.presetName();
  if (!preset.isEmpty()) settings.setValue("scene/preset", preset);
}

}  // namespace fooball::gui
