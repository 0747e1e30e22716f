#include "window/scene_commands.h"

#include <QFile>
#include <QFileInfo>
#include <QUndoStack>
#include <algorithm>
#include <exception>
#include <stdexcept>
#include <string>
#include <string_view>

#include "fooball/presets.h"
#include "fooball/scene_error.h"
#include "fooball/scene_file.h"
#include "frames/run_feed.h"
#include "registry.h"
#include "run/run_controller.h"
#include "sidebar/settings_sidebar.h"
#include "tradeoff.h"
#include "window/main_window.h"

namespace fooball::gui {

namespace {

std::filesystem::path toPath(const QString& path) {
  return std::filesystem::path(QFile::encodeName(path).toStdString());
}

/// "Opened PATH: N balls", with where a saved state came from and, when it breaks a rule of
/// hand-written scenes, the one-line warning naming the worst case: a status line, not an error
/// box, because the state opens exactly as it was saved (DESIGN.md, "Scene files").
QString openedText(const QString& path, const Scene& scene) {
  QString text = QObject::tr("Opened %1: %2 balls").arg(path).arg(scene.balls.size());
  if (!scene.savedFrom) return text;
  text += QObject::tr(", saved from %1 at t = %2 s")
              .arg(QString::fromStdString(scene.savedFrom->backend))
              .arg(scene.savedFrom->time, 0, 'g', 6);
  const std::string warning = savedStateWarning(scene, toPath(path).string());
  if (!warning.empty()) text += QObject::tr(". Warning: %1").arg(QString::fromStdString(warning));
  return text;
}

}  // namespace

bool openSceneFile(MainWindow& window, const QString& path) {
  try {
    const Scene scene = loadSceneFile(toPath(path));
    window.loadScene(scene, QString(), QFileInfo(path).fileName());
    window.showStatus(openedText(path, scene));
    return true;
  } catch (const std::exception& error) {
    const QString message = QString::fromStdString(error.what());
    window.showStatus(
        QObject::tr("Could not open the scene; the current one stays: %1").arg(message));
    window.reportError(QObject::tr("Could not open the scene"), message);
    return false;
  }
}

bool saveSceneFile(MainWindow& window, const QString& path) {
  try {
    fooball::saveSceneFile(window.runs().savedScene(), toPath(path));
    window.showStatus(QObject::tr("Saved %1").arg(path));
    return true;
  } catch (const std::exception& error) {
    const QString message = QString::fromStdString(error.what());
    window.showStatus(message);
    window.reportError(QObject::tr("Could not save the scene"), message);
    return false;
  }
}

bool openPreset(MainWindow& window, const QString& name) {
  try {
    window.loadScene(loadPreset(name.toStdString()), name, name);
    return true;
  } catch (const SceneError& error) {
    const QString message = QString::fromStdString(error.what());
    window.showStatus(message);
    window.reportError(QObject::tr("Could not load the preset"), message);
    window.syncSidebar();
    return false;
  }
}

bool setBallCount(MainWindow& window, std::size_t count) {
  const std::size_t before = window.runs().group().ballCount();
  try {
    window.runs().setBallCount(count);
  } catch (const SceneError& error) {
    window.showStatus(QString::fromStdString(error.what()));
    window.sidebar()->showBallCount(window.runs().group().ballCount());
    return false;
  }
  if (count != before) {
    window.undoStack()->clear();  // balls renumbered or gone (MainWindow::undoStack)
    window.feed().markChange(QObject::tr("%1 balls").arg(count));
  }
  const double scale = window.runs().group().newBallScale();
  if (count > before && scale < 1.0) {
    window.showStatus(
        QObject::tr("Added %L1 balls at %2 % of the size of the balls there, so that they fit")
            .arg(count - before)
            .arg(100.0 * scale, 0, 'g', 2));
  }
  return true;
}

bool openConfiguration(MainWindow& window, const Configuration& configuration) {
  const std::string_view reference = measure::kReferenceBackend;
  const bool hasReference = std::ranges::any_of(
      registeredBackends(), [&](const BackendInfo& info) { return info.name == reference; });
  try {
    createBackend(configuration.spec);  // checks the spec before anything changes
  } catch (const std::invalid_argument& error) {
    window.showStatus(QString::fromStdString(error.what()));
    return false;
  }
  window.loadScene(configuration.scene, configuration.presetName, configuration.sourceName);
  RunController& runs = window.runs();
  while (runs.runCount() > 1)
    runs.removeRun(runs.runCount() - 1);
  runs.setRunSpec(0, configuration.spec);
  if (hasReference && configuration.spec.backend != reference)
    runs.addRun(RunSpec{std::string(reference), {}});
  window.showStatus(QObject::tr("Opened %1 on %2")
                        .arg(configuration.sourceName, runs.labels().join(QObject::tr(" vs "))));
  return true;
}

}  // namespace fooball::gui
