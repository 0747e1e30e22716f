#pragma once

#include <QString>
#include <cstddef>

#include "tools/configuration.h"

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

/// Loads the configuration's scene with run 0 on its spec and, unless that spec is on the
/// reference backend (measure::kReferenceBackend) or there is none, a compare run on the
/// reference at its defaults. A bad spec is reported and nothing changes.
bool openConfiguration(MainWindow& window, const Configuration& configuration);

}  // namespace fooball::gui
