#pragma once

#include <QString>
#include <cstddef>

namespace fooball::gui {

class MainWindow;

/// What File → Open/Save, the preset box and the ball spinner do. Each reports an error to the
/// user (status bar and, for files, the window's error reporter) and keeps the scene it had.

/// Loads a scene file into every run.
bool openSceneFile(MainWindow& window, const QString& path);
/// Saves run 0's state.
bool saveSceneFile(MainWindow& window, const QString& path);
bool openPreset(MainWindow& window, const QString& name);
/// As the spinner: balls added where there is room in every run, or the newest removed.
bool setBallCount(MainWindow& window, std::size_t count);

}  // namespace fooball::gui
