#pragma once

#include <QObject>
#include <QString>

#include "fooball/scene.h"

class QUndoStack;

namespace fooball::gui {

class FrameLoop;
class RunController;
class RunFeed;
class SettingsSidebar;
class SimulationView;

/// The scene the runs started on, and what a load, a restart or a reset brings back in line with
/// them: the view's preset caption, the ball undo stack, the sidebar's controls, the charts.
class SceneSession : public QObject {
  Q_OBJECT

 public:
  /// What follows the scene. `undoStack` holds the ball commands (BallCommands): they name
  /// balls by index and hold their states, so whatever renumbers or replaces the balls clears
  /// it: loading a scene or preset, Restart, Reset scene and a ball-count change.
  struct Parts {
    RunController& runs;
    SimulationView& view;
    SettingsSidebar& sidebar;
    RunFeed& feed;
    FrameLoop& frames;
    QUndoStack& undoStack;
  };

  /// The runs are on the scene of `presetName` (empty for a scene file) called `sourceName`.
  SceneSession(Parts parts, const QString& presetName, const QString& sourceName, QObject* parent);

  /// The preset the scene came from; empty for a scene file.
  const QString& presetName() const { return presetName_; }
  /// The preset's or the scene file's name, as in the title.
  const QString& sourceName() const { return sourceName_; }

  /// Every run starts on `scene` (valid); the sidebar, the charts and the title follow.
  void loadScene(const Scene& scene, const QString& presetName, const QString& sourceName);
  /// Back to the loaded scene at t = 0, keeping the settings of now.
  void restart();
  /// The loaded scene exactly as loaded, sliders at their defaults.
  void resetScene();
  /// Gravity, air resistance, mouse strength and speed back to the loaded scene's and defaults.
  void resetSliders();
  void clearAttractors();

  /// Brings every control in line with the runs (after a load or reset).
  void syncSidebar();
  /// The run list and the readouts after runs changed.
  void showRuns();
  /// The charts and the frame loop's sampling start over on the runs' state now.
  void restartCharts();

 signals:
  /// Another scene was loaded (its name is in the title).
  void sceneLoaded();

 private:
  Parts parts_;
  QString presetName_;
  QString sourceName_;
};

}  // namespace fooball::gui
