#include "control/scene_commands.h"

#include <QFile>
#include <QFileInfo>
#include <QUndoStack>
#include <algorithm>
#include <exception>
#include <stdexcept>
#include <string>
#include <string_view>

#include "control/scene_session.h"
#include "fooball/presets.h"
#include "fooball/scene_error.h"
#include "fooball/scene_file.h"
#include "frames/run_feed.h"
#include "registry.h"
#include "run/run_controller.h"
#include "sidebar/settings_sidebar.h"
#include "tradeoff.h"
#include "widgets/user_messages.h"

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

bool SceneCommands::openSceneFile(const QString& path) {
  try {
    const Scene scene = loadSceneFile(toPath(path));
    parts_.session.loadScene(scene, QString(), QFileInfo(path).fileName());
    parts_.messages.showStatus(openedText(path, scene));
    return true;
  } catch (const std::exception& error) {
    const QString message = QString::fromStdString(error.what());
    parts_.messages.showStatus(
        QObject::tr("Could not open the scene; the current one stays: %1").arg(message));
    parts_.messages.reportError(QObject::tr("Could not open the scene"), message);
    return false;
  }
}

bool SceneCommands::saveSceneFile(const QString& path) {
  try {
    fooball::saveSceneFile(parts_.runs.savedScene(), toPath(path));
    parts_.messages.showStatus(QObject::tr("Saved %1").arg(path));
    return true;
  } catch (const std::exception& error) {
    const QString message = QString::fromStdString(error.what());
    parts_.messages.showStatus(message);
    parts_.messages.reportError(QObject::tr("Could not save the scene"), message);
    return false;
  }
}

bool SceneCommands::openPreset(const QString& name) {
  try {
    parts_.session.loadScene(loadPreset(name.toStdString()), name, name);
    return true;
  } catch (const SceneError& error) {
    const QString message = QString::fromStdString(error.what());
    parts_.messages.showStatus(message);
    parts_.messages.reportError(QObject::tr("Could not load the preset"), message);
    parts_.session.syncSidebar();
    return false;
  }
}

bool SceneCommands::setBallCount(std::size_t count) {
  const std::size_t before = parts_.runs.group().ballCount();
  try {
    parts_.runs.setBallCount(count);
  } catch (const SceneError& error) {
    // Beside the field, where the user looks, until a count is accepted; with what would fit
    // when more balls were asked for than fit.
    QString refusal = QObject::tr("%L1 balls refused (%L2 kept): %3")
                          .arg(count)
                          .arg(before)
                          .arg(QString::fromStdString(error.what()));
    if (count > before) {
      const std::size_t most = parts_.runs.group().mostBallsThatFit();
      if (most < count) refusal += QObject::tr(" — at most %L1 fit").arg(most);
    }
    parts_.sidebar.showBallCountRefusal(refusal);
    parts_.sidebar.showBallCount(before);
    return false;
  }
  parts_.sidebar.showBallCountRefusal(QString());
  if (count != before) {
    parts_.undoStack.clear();  // balls renumbered or gone (SceneSession::Parts)
    parts_.feed.markChange(QObject::tr("%1 balls").arg(count));
  }
  const double scale = parts_.runs.group().newBallScale();
  if (count > before && scale < 1.0) {
    parts_.messages.showStatus(
        QObject::tr("Added %L1 balls at %2 % of the size of the balls there, so that they fit")
            .arg(count - before)
            .arg(100.0 * scale, 0, 'g', 2));
  }
  return true;
}

bool SceneCommands::openConfiguration(const Configuration& configuration) {
  const std::string_view reference = measure::kReferenceBackend;
  const bool hasReference = std::ranges::any_of(
      registeredBackends(), [&](const BackendInfo& info) { return info.name == reference; });
  try {
    createBackend(configuration.spec);  // checks the spec before anything changes
  } catch (const std::invalid_argument& error) {
    parts_.messages.showStatus(QString::fromStdString(error.what()));
    return false;
  }
  parts_.session.loadScene(configuration.scene, configuration.presetName, configuration.sourceName);
  RunController& runs = parts_.runs;
  while (runs.runCount() > 1)
    runs.removeRun(runs.runCount() - 1);
  runs.setRunSpec(0, configuration.spec);
  if (hasReference && configuration.spec.backend != reference)
    runs.addRun(RunSpec{std::string(reference), {}});
  // Loading restarted the charts with the runs shown before: start them over with these.
  parts_.session.restartCharts();
  parts_.messages.showStatus(
      QObject::tr("Opened %1 on %2")
          .arg(configuration.sourceName, runs.labels().join(QObject::tr(" vs "))));
  return true;
}

}  // namespace fooball::gui
