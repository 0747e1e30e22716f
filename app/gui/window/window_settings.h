#pragma once

class QMainWindow;
class QWidget;

namespace fooball::gui {

class FrameLoop;
class RunController;
class SceneSession;
class SimulationView;
class WindowActions;

/// What the remembered settings are read into and written from.
struct RememberedParts {
  QMainWindow& window;  ///< its geometry and dock layout
  const WindowActions& actions;
  const SimulationView& view;
  RunController& runs;
  FrameLoop& frames;
  const SceneSession& session;
};

/// The layout of the keys writeWindowSettings stores. Raise it when a key changes meaning or the
/// window's docks change: a file of another version (an older app's, or a newer one's) still
/// gives its plain values, each checked and clamped, but not its window geometry and dock layout,
/// which only make sense to the window that wrote them.
inline constexpr int kSettingsVersion = 2;  // 2: the Statistics dock

/// Restores what the user chose last time (QSettings): window geometry and dock layout, drawing
/// options, compare layout, mouse tool and speed, then keeps the window fully on a screen.
/// Returns whether a dock layout was restored.
bool readWindowSettings(const RememberedParts& parts);
/// Remembers the same, plus run 0's backend and the preset, for the next start.
void writeWindowSettings(const RememberedParts& parts);
/// Forgets everything the app remembers (fooball --reset-settings): the next start is a first
/// start.
void forgetWindowSettings();

/// Moves `window`, and shrinks it where it is larger, so that all of it lies on the available
/// area (without panels) of the screen it is mostly on. A remembered geometry may come from
/// another monitor layout, and a default size from a larger screen.
void keepFullyOnScreen(QWidget& window);

}  // namespace fooball::gui
