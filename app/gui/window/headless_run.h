#pragma once

#include <QSize>
#include <QString>
#include <optional>

#include "recording/recording_session.h"

namespace fooball::gui {

class MainWindow;

/// `--frames N [--screenshot FILE] [--size WxH]`: shows `window` at `size` (offscreen without a
/// display), runs `frames` frames of 1/60 s of physics plus a full repaint each, prints the mean
/// frame time in ms to stdout, then saves the window as PNG if asked. Returns the exit code.
int runHeadless(MainWindow& window, int frames, const std::optional<QString>& screenshotPath,
                const std::optional<QSize>& size);

/// `--record FILE --frames N [--size WxH] [--fps N] [--record-charts] [--screenshot FILE]`:
/// shows `window` (offscreen without a display) with only what is recorded in it, at the
/// video's size, and records `frames` frames of exactly 1/fps s of simulation each
/// (RecordingSession); prints what it wrote to stdout, then saves the last recorded picture as
/// PNG if asked. An interrupt (Ctrl+C, SIGTERM) ends the video early, finished and playable.
/// Returns the exit code: 0, or 1 with one line on stderr (a file that cannot be written).
int recordHeadless(MainWindow& window, const RecordingSettings& settings, int frames,
                   const std::optional<QString>& screenshotPath);

}  // namespace fooball::gui
