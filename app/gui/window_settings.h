#pragma once

namespace fooball::gui {

class MainWindow;

/// Restores what the user chose last time (QSettings): window geometry and dock layout, drawing
/// options, compare layout, mouse tool and speed. Returns whether a dock layout was restored.
bool readWindowSettings(MainWindow& window);
/// Remembers the same, plus run 0's backend and the preset, for the next start.
void writeWindowSettings(const MainWindow& window);

}  // namespace fooball::gui
