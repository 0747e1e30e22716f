#pragma once

#include <cstddef>

#include "fooball/scene.h"

class QUndoStack;

namespace fooball::gui {

class BallInspector;
class RunController;
class RunFeed;
class UserMessages;

/// What the inspector's edits, its Delete button and the Delete key do, each an undoable command
/// on the ball undo stack (SceneSession::Parts), and Edit → Undo / Redo. A refused change (an
/// edit onto another ball, an undo whose place is taken now) says why in plain words in the
/// status bar (and the inspector, for an edit) and changes nothing.
class BallCommands {
 public:
  struct Parts {
    RunController& runs;
    RunFeed& feed;
    QUndoStack& undoStack;
    BallInspector& inspector;
    UserMessages& messages;
  };

  explicit BallCommands(Parts parts) : parts_(parts) {}

  /// Applies the inspector's `edited` ball to every run (RunGroup::editBall: the mass follows
  /// the radius unless the user chose it).
  void editBall(std::size_t index, const BallDef& edited);
  /// Removes ball `index` from every run, with a chart marker.
  void deleteBall(std::size_t index);
  void undo() { undoOrRedo(true); }
  void redo() { undoOrRedo(false); }

 private:
  void undoOrRedo(bool undo);

  Parts parts_;
};

}  // namespace fooball::gui
