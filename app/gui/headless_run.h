#pragma once

#include <QSize>
#include <QString>
#include <optional>

namespace fooball::gui {

class MainWindow;

/// `--frames N [--screenshot FILE] [--size WxH]`: shows `window` at `size` (offscreen without a
/// display), runs `frames` frames of 1/60 s of physics plus a full repaint each, prints the mean
/// frame time in ms to stdout, then saves the window as PNG if asked. Returns the exit code.
int runHeadless(MainWindow& window, int frames, const std::optional<QString>& screenshotPath,
                const std::optional<QSize>& size);

}  // namespace fooball::gui
