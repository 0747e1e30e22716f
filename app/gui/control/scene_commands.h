#pragma once

#include <QString>
#include <cstddef>

#include "tools/configuration.h"

class QUndoStack;

namespace fooball::gui {

class RunController;
class RunFeed;
class SceneSession;
class SettingsSidebar;
class UserMessages;

/// What File → Open/Save, the preset box and the ball spinner do. Each reports an error to the
/// user (status bar and, for files, the error reporter) and keeps the scene it had.
class SceneCommands {
 public:
  struct Parts {
    SceneSession& session;
    RunController& runs;
    SettingsSidebar& sidebar;
    RunFeed& feed;
    QUndoStack& undoStack;  ///< the ball commands, cleared when balls are renumbered
    UserMessages& messages;
  };

  explicit SceneCommands(Parts parts) : parts_(parts) {}

  /// Loads a scene file into every run.
  bool openSceneFile(const QString& path);
  /// Saves run 0's state.
  bool saveSceneFile(const QString& path);
  bool openPreset(const QString& name);
  /// As the spinner: balls added where there is room in every run, or the newest removed.
  bool setBallCount(std::size_t count);

  /// Loads the configuration's scene with run 0 on its spec and, unless that spec is on the
  /// reference backend (measure::kReferenceBackend) or there is none, a compare run on the
  /// reference at its defaults. A bad spec is reported and nothing changes.
  bool openConfiguration(const Configuration& configuration);

 private:
  Parts parts_;
};

}  // namespace fooball::gui
