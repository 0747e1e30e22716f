#include "window/recording_target.h"

#include <QDockWidget>

#include "window/main_window.h"

namespace fooball::gui {

RecordingTarget recordingTargetOf(MainWindow& window) {
  return {*window.view(), *window.charts(), *window.chartsDock(), window.frames(), window.runs()};
}

}  // namespace fooball::gui
