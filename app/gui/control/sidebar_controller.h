#pragma once

#include <QObject>

#include "fooball/run_spec.h"

namespace fooball::gui {

class BallCommands;
class FrameLoop;
class RunController;
class RunFeed;
class SceneCommands;
class SceneSession;
class SettingsSidebar;
class SimulationView;
class UserMessages;

/// What each control of the settings sidebar does: every signal of SettingsSidebar, its run
/// list and its inspector, connected to the runs, the scene and ball commands and the frame
/// loop, with a chart marker for each change and the error in the status bar when the runs
/// refuse one. (The drawing check boxes mirror the View menu: WindowActions.)
class SidebarController : public QObject {
  Q_OBJECT

 public:
  struct Parts {
    SettingsSidebar& sidebar;
    RunController& runs;
    SceneSession& session;
    SceneCommands& scenes;
    BallCommands& balls;
    RunFeed& feed;
    FrameLoop& frames;
    SimulationView& view;
    UserMessages& messages;
  };

  SidebarController(Parts parts, QObject* parent);

 private:
  void connectScene();
  void connectWorld();
  void connectMouse();
  void connectRunList();
  void connectInspector();

  void applyGravity(double magnitude);
  /// A new run; every run restarts from run 0's state (RunController::runsRestarted marks it).
  void addRun(const RunSpec& spec);
  void removeRun(int index);
  /// Run `index` continues on `backend` (its default options) from its own state.
  void setRunBackend(int index, const QString& backend);
  void setBackendOption(int index, const QString& name, double value);
  void showBaseline(bool on);

  Parts parts_;
};

}  // namespace fooball::gui
