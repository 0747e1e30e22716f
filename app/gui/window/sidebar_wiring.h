#pragma once

namespace fooball::gui {

class MainWindow;

/// What each control of the settings sidebar does: every signal of SettingsSidebar, its run
/// list and its inspector, connected to the runs, with a chart marker for each change and the
/// error in the status bar when the runs refuse one.
void wireSidebar(MainWindow& window);
/// The mouse tools on the simulation view.
void wireView(MainWindow& window);

/// Gravity, air resistance, mouse strength and speed back to the loaded scene's and defaults.
void resetSliders(MainWindow& window);
void clearAttractors(MainWindow& window);

}  // namespace fooball::gui
