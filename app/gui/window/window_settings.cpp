#include "window/window_settings.h"

#include <QAction>
#include <QGuiApplication>
#include <QMainWindow>
#include <QScreen>
#include <QSettings>
#include <algorithm>
#include <cmath>
#include <limits>

#include "control/scene_session.h"
#include "frames/frame_loop.h"
#include "run/run_controller.h"
#include "view/simulation_view.h"
#include "window/window_actions.h"

namespace fooball::gui {

namespace {

constexpr double kMinTimeScale = 0.05;
constexpr double kMaxTimeScale = 8.0;

/// The number stored under `key`, clamped to [low, high]; `fallback` when it is missing or not a
/// finite number (a hand-edited or damaged file).
double readNumber(const QSettings& settings, const QString& key, double fallback, double low,
                  double high) {
  bool ok = false;
  const double value = settings.value(key, fallback).toDouble(&ok);
  return ok && std::isfinite(value) ? std::clamp(value, low, high) : fallback;
}

}  // namespace

bool readWindowSettings(const RememberedParts& parts) {
  QMainWindow& window = parts.window;
  QSettings settings;
  bool restored = false;
  if (settings.value("settings/version").toInt() == kSettingsVersion) {
    window.restoreGeometry(settings.value("window/geometry").toByteArray());
    restored = window.restoreState(settings.value("window/state").toByteArray());
  }
  keepFullyOnScreen(window);
  const WindowActions& actions = parts.actions;
  actions.temperature()->setChecked(settings.value("drawing/temperature", false).toBool());
  actions.tethers()->setChecked(settings.value("drawing/tethers", true).toBool());
  actions.velocityVectors()->setChecked(settings.value("drawing/velocityVectors", false).toBool());
  actions.centreOfMass()->setChecked(settings.value("drawing/centreOfMass", false).toBool());
  actions.lookFor()->setChecked(settings.value("drawing/lookFor", true).toBool());
  const bool sideBySide = settings.value("drawing/sideBySide", false).toBool();
  (sideBySide ? actions.sideBySide() : actions.overlay())->trigger();
  const auto mode = static_cast<MouseMode>(
      std::clamp(settings.value("mouse/mode", 0).toInt(), 0, int(MouseMode::Slingshot)));
  const auto scope = static_cast<Scope>(
      std::clamp(settings.value("mouse/scope", 0).toInt(), 0, int(Scope::Selected)));
  const double strength = readNumber(settings, "mouse/strength", Interactions::kDefaultStrength,
                                     0.0, std::numeric_limits<double>::max());
  parts.runs.changeTools([&](RunGroup& group) {
    group.setMouseMode(mode);
    group.setScope(scope);
    group.setStrength(strength);
  });
  parts.frames.setTimeScale(readNumber(settings, "time/scale", FrameLoop::kDefaultTimeScale,
                                       kMinTimeScale, kMaxTimeScale));
  return restored;
}

void writeWindowSettings(const RememberedParts& parts) {
  QSettings settings;
  const QMainWindow& window = parts.window;
  const SimulationView& view = parts.view;
  const RunGroup& group = parts.runs.group();
  settings.setValue("settings/version", kSettingsVersion);
  settings.setValue("window/geometry", window.saveGeometry());
  settings.setValue("window/state", window.saveState());
  settings.setValue("drawing/temperature", view.temperatureColouring());
  settings.setValue("drawing/tethers", view.tethers());
  settings.setValue("drawing/velocityVectors", view.velocityVectors());
  settings.setValue("drawing/centreOfMass", view.centreOfMass());
  settings.setValue("drawing/lookFor", view.lookForShown());
  settings.setValue("drawing/sideBySide", view.compareLayout() == CompareLayout::SideBySide);
  settings.setValue("mouse/mode", int(group.interactions().mode));
  settings.setValue("mouse/scope", int(group.interactions().scope));
  settings.setValue("mouse/strength", group.interactions().strength);
  settings.setValue("time/scale", parts.frames.timeScale());
  settings.setValue("run/backend", QString::fromStdString(group.spec(0).backend));
  const QString preset = parts.session.presetName();
  if (!preset.isEmpty()) settings.setValue("scene/preset", preset);
}

void forgetWindowSettings() {
  QSettings().clear();
}

void keepFullyOnScreen(QWidget& window) {
  QScreen* screen = QGuiApplication::screenAt(window.geometry().center());
  if (!screen) screen = QGuiApplication::primaryScreen();
  if (!screen) return;
  const QRect available = screen->availableGeometry();
  // The frame (title bar, borders) is the window manager's, known only once shown: before that
  // frameGeometry() is geometry() and the margins are 0.
  const QRect frame = window.frameGeometry();
  const QSize margins = frame.size() - window.geometry().size();
  const QSize fitting = window.size().boundedTo(available.size() - margins);
  if (fitting != window.size()) window.resize(fitting);  // no smaller than its minimum size
  // On a screen smaller than the window's minimum size, its top-left corner (the title bar and
  // the menus) stays on the screen.
  const QSize outer = window.size() + margins;
  const int x =
      std::max(available.left(), std::min(frame.x(), available.right() + 1 - outer.width()));
  const int y =
      std::max(available.top(), std::min(frame.y(), available.bottom() + 1 - outer.height()));
  if (QPoint(x, y) != frame.topLeft()) window.move(x, y);  // move() places the frame
}

}  // namespace fooball::gui
