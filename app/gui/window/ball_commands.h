#pragma once

#include <cstddef>

#include "fooball/scene.h"

namespace fooball::gui {

class MainWindow;

/// What the inspector's edits, its Delete button and the Delete key do, each an undoable command
/// on the window's undo stack (MainWindow::undoStack), and Edit → Undo / Redo. A refused change
/// (an edit onto another ball, an undo whose place is taken now) says why in plain words in the
/// status bar (and the inspector, for an edit) and changes nothing.

/// Applies the inspector's `edited` ball to every run (RunGroup::editBall: the mass follows the
/// radius unless the user chose it).
void editBall(MainWindow& window, std::size_t index, const BallDef& edited);
/// Removes ball `index` from every run, with a chart marker.
void deleteBall(MainWindow& window, std::size_t index);
void undoBallChange(MainWindow& window);
void redoBallChange(MainWindow& window);

}  // namespace fooball::gui
