#pragma once

#include "recording/recording_frame_source.h"

namespace fooball::gui {

class MainWindow;

/// The parts of `window` a recording draws and drives (File → Record…, --record).
RecordingTarget recordingTargetOf(MainWindow& window);

}  // namespace fooball::gui
