#include "control/sidebar_controller.h"

#include <QStringList>
#include <stdexcept>

#include "control/ball_commands.h"
#include "control/scene_commands.h"
#include "control/scene_session.h"
#include "fooball/number_text.h"
#include "frames/frame_loop.h"
#include "frames/run_feed.h"
#include "run/run_controller.h"
#include "sidebar/ball_inspector.h"
#include "sidebar/run_list_editor.h"
#include "sidebar/settings_sidebar.h"
#include "view/simulation_view.h"
#include "widgets/number_format.h"
#include "widgets/user_messages.h"

namespace fooball::gui {

namespace {

/// The chart marker for a change of walls: "left wall off", "top wall on".
QString wallsChangeLabel(const Walls& before, const Walls& after) {
  QStringList changes;
  const auto add = [&](bool was, bool is, const QString& wall) {
    if (was != is)
      changes.append(is ? QObject::tr("%1 wall on").arg(wall)
                        : QObject::tr("%1 wall off").arg(wall));
  };
  add(before.left, after.left, QObject::tr("left"));
  add(before.right, after.right, QObject::tr("right"));
  add(before.bottom, after.bottom, QObject::tr("bottom"));
  add(before.top, after.top, QObject::tr("top"));
  return changes.join(QStringLiteral(", "));
}

}  // namespace

SidebarController::SidebarController(Parts parts, QObject* parent)
    : QObject(parent), parts_(parts) {
  connectScene();
  connectWorld();
  connectMouse();
  connectRunList();
  connectInspector();
}

void SidebarController::connectScene() {
  SettingsSidebar* s = &parts_.sidebar;
  SceneCommands& scenes = parts_.scenes;
  SceneSession* session = &parts_.session;
  connect(s, &SettingsSidebar::presetChosen, this,
          [&scenes](const QString& name) { scenes.openPreset(name); });
  connect(s, &SettingsSidebar::ballCountChosen, this,
          [&scenes](int count) { scenes.setBallCount(static_cast<std::size_t>(count)); });
  connect(s, &SettingsSidebar::restartRequested, session, &SceneSession::restart);
  connect(s, &SettingsSidebar::resetSceneRequested, session, &SceneSession::resetScene);
  connect(s, &SettingsSidebar::resetSlidersRequested, session, &SceneSession::resetSliders);
}

void SidebarController::connectWorld() {
  SettingsSidebar* s = &parts_.sidebar;
  RunController& runs = parts_.runs;
  RunFeed& feed = parts_.feed;
  connect(s, &SettingsSidebar::gravityChosen, this, &SidebarController::applyGravity);
  connect(s, &SettingsSidebar::airResistanceChosen, this, [&runs, &feed](double coefficient) {
    runs.changeWorld([&](WorldSettings& world) { world.airResistance = coefficient; });
    feed.markChange(tr("air resistance %1 1/s").arg(formatNumber(coefficient)),
                    QStringLiteral("air resistance"));
  });
  connect(s, &SettingsSidebar::timeScaleChosen, this, [this](double timeScale) {
    parts_.frames.setTimeScale(timeScale);
    parts_.feed.markChange(tr("speed %1×").arg(formatNumber(timeScale)), QStringLiteral("speed"));
  });
  connect(s, &SettingsSidebar::dtChosen, this, [&runs, &feed](double dt) {
    runs.change([&](RunGroup& group) { group.setDt(dt); });
    feed.markChange(tr("dt %1 s").arg(QString::fromStdString(exactNumberText(dt))),
                    QStringLiteral("dt"));
  });
  connect(s, &SettingsSidebar::ballCollisionsToggled, this, [&runs, &feed](bool on) {
    runs.changeWorld([&](WorldSettings& world) { world.ballCollisions = on; });
    feed.markChange(on ? tr("collisions on") : tr("collisions off"));
  });
  connect(s, &SettingsSidebar::wallsChosen, this, [this](const Walls& walls) {
    const QString label = wallsChangeLabel(parts_.runs.group().world().walls, walls);
    parts_.runs.changeWorld([&](WorldSettings& world) { world.walls = walls; });
    parts_.feed.markChange(label);
    parts_.view.update();
  });
}

void SidebarController::connectMouse() {
  SettingsSidebar* s = &parts_.sidebar;
  RunController& runs = parts_.runs;
  connect(s, &SettingsSidebar::strengthChosen, this, [this](double strength) {
    parts_.runs.changeTools([&](RunGroup& group) { group.setStrength(strength); });
    parts_.feed.markChange(tr("mouse strength %1").arg(formatNumber(strength)),
                           QStringLiteral("mouse strength"));
  });
  connect(s, &SettingsSidebar::mouseModeChosen, this, [&runs](MouseMode mode) {
    runs.changeTools([&](RunGroup& group) { group.setMouseMode(mode); });
  });
  connect(s, &SettingsSidebar::scopeChosen, this, [&runs](Scope scope) {
    runs.changeTools([&](RunGroup& group) { group.setScope(scope); });
  });
  connect(s, &SettingsSidebar::clearAttractorsRequested, &parts_.session,
          &SceneSession::clearAttractors);
}

void SidebarController::connectRunList() {
  RunListEditor* list = parts_.sidebar.runList();
  connect(list, &RunListEditor::backendChosen, this, &SidebarController::setRunBackend);
  connect(list, &RunListEditor::addRunRequested, this, [this](const QString& name) {
    addRun(RunSpec{name.toStdString(), {}});
  });
  connect(list, &RunListEditor::removeRunRequested, this, &SidebarController::removeRun);
  connect(list, &RunListEditor::optionChanged, this, &SidebarController::setBackendOption);
  connect(list, &RunListEditor::baselineToggled, this, &SidebarController::showBaseline);
}

void SidebarController::connectInspector() {
  BallInspector* inspector = parts_.sidebar.inspector();
  connect(inspector, &BallInspector::ballEdited, this,
          [this](std::size_t index, const BallDef& ball) {
            parts_.balls.editBall(index, ball);
            parts_.view.update();
          });
  connect(inspector, &BallInspector::deleteRequested, this,
          [this](std::size_t index) { parts_.balls.deleteBall(index); });
}

void SidebarController::applyGravity(double magnitude) {
  const RunGroup& group = parts_.runs.group();
  // Keep the direction gravity has (or had in the scene); straight down when there is none.
  Vec2 direction{0.0, -1.0};
  const Vec2 now = group.world().gravity;
  const Vec2 loaded = group.loadedScene().world.gravity;
  if (length(now) > 0.0) {
    direction = now / length(now);
  } else if (length(loaded) > 0.0) {
    direction = loaded / length(loaded);
  }
  parts_.runs.changeWorld([&](WorldSettings& world) { world.gravity = magnitude * direction; });
  parts_.feed.markChange(tr("gravity %1 m/s²").arg(formatNumber(magnitude)),
                         QStringLiteral("gravity"));
}

void SidebarController::addRun(const RunSpec& spec) {
  RunController& runs = parts_.runs;
  const bool wasComparing = runs.comparing();
  try {
    runs.addRun(spec);
  } catch (const std::invalid_argument& error) {
    parts_.messages.showStatus(QString::fromStdString(error.what()));
    return;
  }
  if (!wasComparing) runs.setBaseline(true);  // compare mode shows chaos unless hidden
  parts_.feed.addRun();
  parts_.session.showRuns();
}

void SidebarController::removeRun(int index) {
  if (parts_.runs.runCount() < 2) return;
  parts_.runs.removeRun(index);
  parts_.feed.removeRun(index);
  parts_.feed.markChange(tr("run %1 removed").arg(index));
}

void SidebarController::setRunBackend(int index, const QString& backend) {
  RunController& runs = parts_.runs;
  if (backend.toStdString() == runs.group().spec(std::size_t(index)).backend) return;
  try {
    runs.setRunSpec(index, RunSpec{backend.toStdString(), {}});
  } catch (const std::invalid_argument& error) {
    parts_.messages.showStatus(QString::fromStdString(error.what()));
    parts_.session.showRuns();
    return;
  }
  parts_.feed.renameRun(index);
  parts_.feed.markChange(tr("run %1 → %2").arg(index).arg(backend));
}

void SidebarController::setBackendOption(int index, const QString& name, double value) {
  try {
    parts_.runs.setBackendOption(index, name, value);
    // The value as the run spec has it: "substeps = 8", "rest_bounce_time = 1e-06".
    parts_.feed.markChange(
        QStringLiteral("%1 = %2").arg(name, QString::fromStdString(exactNumberText(value))),
        QStringLiteral("run %1 %2").arg(index).arg(name));
  } catch (const std::invalid_argument& error) {
    parts_.messages.showStatus(QString::fromStdString(error.what()));
    parts_.sidebar.runList()->showRuns(parts_.runs.group());
  }
}

void SidebarController::showBaseline(bool on) {
  parts_.runs.setBaseline(on);
  parts_.feed.showBaseline(on);
  parts_.feed.markChange(on ? tr("baseline on") : tr("baseline off"));
}

}  // namespace fooball::gui
