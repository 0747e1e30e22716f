#include "control/scene_session.h"

#include <QUndoStack>

#include "fooball/presets.h"
#include "frames/frame_loop.h"
#include "frames/run_feed.h"
#include "run/run_controller.h"
#include "sidebar/run_list_editor.h"
#include "sidebar/settings_sidebar.h"
#include "view/simulation_view.h"

namespace fooball::gui {

SceneSession::SceneSession(Parts parts, const QString& presetName, const QString& sourceName,
                           QObject* parent)
    : QObject(parent), parts_(parts), presetName_(presetName), sourceName_(sourceName) {
  parts_.view.setPreset(findPreset(presetName_.toStdString()));
}

void SceneSession::loadScene(const Scene& scene, const QString& presetName,
                             const QString& sourceName) {
  presetName_ = presetName;
  sourceName_ = sourceName;
  parts_.runs.loadScene(scene);
  parts_.view.setPreset(findPreset(presetName_.toStdString()));
  parts_.undoStack.clear();  // other balls (Parts::undoStack)
  syncSidebar();
  restartCharts();
  emit sceneLoaded();
}

void SceneSession::restart() {
  parts_.runs.restart();
  parts_.undoStack.clear();  // the balls as loaded (Parts::undoStack)
  restartCharts();
}

void SceneSession::resetScene() {
  parts_.runs.loadScene(parts_.runs.group().loadedScene());
  parts_.undoStack.clear();  // the balls as loaded (Parts::undoStack)
  resetSliders();
  syncSidebar();
  restartCharts();
}

void SceneSession::resetSliders() {
  RunController& runs = parts_.runs;
  const Scene& loaded = runs.group().loadedScene();
  runs.changeWorld([&](WorldSettings& world) {
    world.gravity = loaded.world.gravity;
    world.airResistance = loaded.world.airResistance;
  });
  runs.changeTools([](RunGroup& group) { group.setStrength(Interactions::kDefaultStrength); });
  parts_.frames.setTimeScale(FrameLoop::kDefaultTimeScale);
  parts_.sidebar.showWorld(runs.group().world());
  parts_.sidebar.showStrength(Interactions::kDefaultStrength);
  parts_.sidebar.showTimeScale(FrameLoop::kDefaultTimeScale);
  parts_.feed.markChange(tr("sliders reset"));
}

void SceneSession::clearAttractors() {
  parts_.runs.changeTools([](RunGroup& group) { group.clearAttractors(); });
  parts_.sidebar.showAttractorCount(0);
  parts_.view.update();
}

void SceneSession::syncSidebar() {
  const RunGroup& group = parts_.runs.group();
  SettingsSidebar& sidebar = parts_.sidebar;
  const SimulationView& view = parts_.view;
  sidebar.showSceneSource(presetName_, sourceName_);
  sidebar.showBallCount(group.ballCount());
  sidebar.showWorld(group.world());
  sidebar.showStrength(group.interactions().strength);
  sidebar.showTimeScale(parts_.frames.timeScale());
  sidebar.showDt(group.dt());
  sidebar.showMouseMode(group.interactions().mode);
  sidebar.showScope(group.interactions().scope);
  sidebar.showAttractorCount(group.interactions().attractors().size());
  sidebar.showDrawing(view.temperatureColouring(), view.tethers(), view.velocityVectors(),
                      view.centreOfMass());
  sidebar.runList()->showCompareLayout(view.compareLayout());
  showRuns();
  parts_.feed.showSelectedBall();
}

void SceneSession::showRuns() {
  parts_.sidebar.runList()->showRuns(parts_.runs.group());
  parts_.feed.showRuns();
}

void SceneSession::restartCharts() {
  parts_.frames.restartSampling();
  parts_.feed.restart();
}

}  // namespace fooball::gui
