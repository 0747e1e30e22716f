#pragma once

#include <QSize>
#include <QString>
#include <QStringList>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <vector>

#include "fooball/run_spec.h"
#include "fooball/vec2.h"

namespace fooball::gui {

/// `fooball [--scene FILE | --preset NAME] [--backend SPEC] [--compare SPEC]… [--size WxH]
///          [--balls N] [--show ITEM,…] [--attractor X,Y]… [--frames N] [--screenshot FILE.png]
///          [--record FILE.{mp4,webm,gif} [--fps N] [--record-charts]]
///          [--reset-settings] [--version]`
/// (DESIGN.md, "fooball (GUI)"; --balls, --show and --attractor are extras for benchmarks and
/// reproducible screenshots).
struct CommandLine {
  std::optional<QString> sceneFile;
  std::optional<QString> preset;
  std::optional<RunSpec> backend;    ///< run 0's
  std::vector<RunSpec> compare;      ///< the other runs, in order (at most 7)
  std::optional<QSize> size;         ///< px, the window's
  std::optional<std::size_t> balls;  ///< ball count after loading, like the spinner
  std::optional<int> frames;         ///< run this many frames, print the mean frame time, exit
  std::optional<QString> screenshot;
  /// --record: a video of `frames` frames, each 1/fps s of video and of simulation (--size is
  /// then the video's size, 1280x720 unless given).
  std::optional<QString> record;
  int recordFramesPerSecond = 60;  ///< --fps
  bool recordCharts = false;       ///< --record-charts: the charts beside the box too
  /// Drawing options to turn on: "temperature", "vectors", "centre-of-mass", "side-by-side";
  /// "statistics" opens the Statistics dock.
  QStringList show;
  std::vector<Vec2> attractors;  ///< m, permanent attractors placed at the start
  bool help = false;
  bool version = false;
  bool resetSettings = false;  ///< forget every remembered setting before starting

  /// Runs without a window system of its own: --frames, --screenshot or --record.
  bool headless() const {
    return frames.has_value() || screenshot.has_value() || record.has_value();
  }
};

/// A bad argument; what() is one line naming it.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// `arguments` includes the program name first, as QCoreApplication::arguments() does.
/// Throws UsageError.
CommandLine parseCommandLine(const QStringList& arguments);

QString usageText();

/// px: --record's video size, --size or 1280x720.
QSize recordingSize(const CommandLine& line);

}  // namespace fooball::gui
