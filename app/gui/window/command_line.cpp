#include "window/command_line.h"

#include <QCommandLineParser>
#include <cmath>
#include <string>

#include "fooball/run_group.h"
#include "fooball/scene.h"
#include "registry.h"
#include "video_format.h"

namespace fooball::gui {

namespace {

const QStringList kShowItems{QStringLiteral("temperature"), QStringLiteral("vectors"),
                             QStringLiteral("centre-of-mass"), QStringLiteral("side-by-side"),
                             QStringLiteral("statistics")};

/// A run spec whose backend and options exist (by making the backend once).
RunSpec checkedRunSpec(const QString& text) {
  try {
    RunSpec spec = parseRunSpec(text.toStdString());
    createBackend(spec);
    return spec;
  } catch (const std::invalid_argument& error) {
    throw UsageError(error.what());
  }
}

/// Pixels each way: a window smaller than the layout's minimum or larger than any screen is a
/// mistake, not a wish.
constexpr int kMinWindowSide = 320;
constexpr int kMaxWindowSide = 16384;

QSize parseSize(const QString& text) {
  const QStringList parts = text.split(QLatin1Char('x'));
  bool widthOk = false;
  bool heightOk = false;
  const int width = parts.size() == 2 ? parts[0].toInt(&widthOk) : 0;
  const int height = parts.size() == 2 ? parts[1].toInt(&heightOk) : 0;
  if (!widthOk || !heightOk || width < kMinWindowSide || height < kMinWindowSide ||
      width > kMaxWindowSide || height > kMaxWindowSide) {
    throw UsageError(QStringLiteral("--size: expected WIDTHxHEIGHT in pixels, each from %1 to %2 "
                                    "(got '%3')")
                         .arg(kMinWindowSide)
                         .arg(kMaxWindowSide)
                         .arg(text)
                         .toStdString());
  }
  return {width, height};
}

long long parseCount(const QString& text, const QString& option, long long minimum,
                     long long maximum) {
  bool ok = false;
  const long long value = text.toLongLong(&ok);
  if (!ok || value < minimum || value > maximum) {
    throw UsageError(QStringLiteral("--%1: expected a whole number from %2 to %3 (got '%4')")
                         .arg(option)
                         .arg(minimum)
                         .arg(maximum)
                         .arg(text)
                         .toStdString());
  }
  return value;
}

/// --record's file type, size and frame rate go together, and it needs --frames.
void checkRecording(const CommandLine& line) {
  const std::string path = line.record->toStdString();
  const auto format = video::videoFormatOf(path);
  if (!format) throw UsageError("--record: " + video::unknownExtensionMessage(path));
  if (!line.frames) throw UsageError("--record: give the video's length with --frames N");
  const QSize size = recordingSize(line);
  const std::string problem =
      video::checkVideoSettings({*format, size.width(), size.height(), line.recordFramesPerSecond});
  if (!problem.empty()) throw UsageError("--record: " + problem);
}

}  // namespace

QSize recordingSize(const CommandLine& line) {
  return line.size.value_or(QSize(1280, 720));
}

QString usageText() {
  return QStringLiteral(
      "Usage: fooball [OPTIONS]\n"
      "\n"
      "FooBall: bouncing balls on interchangeable physics backends, side by side.\n"
      "It opens on the built-in default scene (or --scene, --preset) with one run, and\n"
      "one more run per --compare.\n"
      "\n"
      "Options:\n"
      "  --scene FILE       open a scene file (JSON)\n"
      "  --preset NAME      start on a built-in scene (fooball-cli list shows them)\n"
      "  --backend SPEC     run 0's method: NAME[:KEY=VALUE[,KEY=VALUE]...], e.g.\n"
      "                     elastic:substeps=16 (fooball-cli list shows backends, options)\n"
      "  --compare SPEC     start in compare mode with one more run of SPEC (repeatable,\n"
      "                     up to 7); every run steps the same scene in lockstep\n"
      "  --size WxH         the window's size in pixels, e.g. 1440x900\n"
      "  --balls N          add or remove balls after loading, like the ball spinner\n"
      "  --show ITEM,...    turn on drawing options: temperature, vectors, centre-of-mass,\n"
      "                     side-by-side (compare layout); statistics opens that dock\n"
      "  --attractor X,Y    place a permanent attractor at (X, Y) metres (repeatable)\n"
      "  --frames N         run N frames (physics for 1/60 s + drawing each), print the mean\n"
      "                     frame time in ms and exit; works without a display\n"
      "  --screenshot FILE  after the frames, save the window as PNG (with --record: the\n"
      "                     last recorded picture, before encoding)\n"
      "  --record FILE      record the --frames frames to a video: FILE.mp4 (H.264),\n"
      "                     FILE.webm (VP9) or FILE.gif; the box with its legend row and\n"
      "                     run labels at --size (the video's, default 1280x720); each\n"
      "                     frame holds 1/fps s of simulation; works without a display\n"
      "  --fps N            the recording's frame rate: 60 (default), 50, 30, 25 or 24;\n"
      "                     a GIF takes 50, 25, 20 or 10\n"
      "  --record-charts    record the charts beside the box too\n"
      "  --reset-settings   forget the remembered window layout, scene, backend and\n"
      "                     drawing options, and start as on first use\n"
      "  --version          print the version and exit\n"
      "  -h, --help         show this help\n");
}

CommandLine parseCommandLine(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
  const QCommandLineOption scene(QStringLiteral("scene"), QString(), QStringLiteral("FILE"));
  const QCommandLineOption preset(QStringLiteral("preset"), QString(), QStringLiteral("NAME"));
  const QCommandLineOption backend(QStringLiteral("backend"), QString(), QStringLiteral("SPEC"));
  const QCommandLineOption compare(QStringLiteral("compare"), QString(), QStringLiteral("SPEC"));
  const QCommandLineOption size(QStringLiteral("size"), QString(), QStringLiteral("WxH"));
  const QCommandLineOption balls(QStringLiteral("balls"), QString(), QStringLiteral("N"));
  const QCommandLineOption frames(QStringLiteral("frames"), QString(), QStringLiteral("N"));
  const QCommandLineOption screenshot(QStringLiteral("screenshot"), QString(),
                                      QStringLiteral("FILE"));
  const QCommandLineOption show(QStringLiteral("show"), QString(), QStringLiteral("ITEMS"));
  const QCommandLineOption attractor(QStringLiteral("attractor"), QString(), QStringLiteral("X,Y"));
  const QCommandLineOption record(QStringLiteral("record"), QString(), QStringLiteral("FILE"));
  const QCommandLineOption fps(QStringLiteral("fps"), QString(), QStringLiteral("N"));
  const QCommandLineOption recordCharts(QStringLiteral("record-charts"));
  const QCommandLineOption resetSettings(QStringLiteral("reset-settings"));
  const QCommandLineOption version(QStringLiteral("version"));
  const QCommandLineOption help(QStringList{QStringLiteral("h"), QStringLiteral("help")});
  parser.addOptions({scene, preset, backend, compare, size, balls, frames, screenshot, show,
                     attractor, record, fps, recordCharts, resetSettings, version, help});

  if (!parser.parse(arguments)) throw UsageError(parser.errorText().toStdString());
  if (!parser.positionalArguments().isEmpty()) {
    throw UsageError("unexpected argument '" + parser.positionalArguments().front().toStdString() +
                     "' (see --help)");
  }

  CommandLine line;
  line.help = parser.isSet(help);
  line.version = parser.isSet(version);
  line.resetSettings = parser.isSet(resetSettings);
  const auto single = [&](const QCommandLineOption& option) -> std::optional<QString> {
    if (!parser.isSet(option)) return std::nullopt;
    const QStringList values = parser.values(option);
    if (values.size() > 1) {
      throw UsageError("--" + option.names().front().toStdString() + " given more than once");
    }
    return values.front();
  };
  line.sceneFile = single(scene);
  line.preset = single(preset);
  if (line.sceneFile && line.preset) throw UsageError("--scene and --preset exclude each other");
  if (const auto text = single(backend)) line.backend = checkedRunSpec(*text);
  const QStringList compares = parser.values(compare);
  if (compares.size() > qsizetype(RunGroup::kMaxRuns - 1)) {
    throw UsageError("--compare: at most " + std::to_string(RunGroup::kMaxRuns - 1) +
                     " compare runs (got " + std::to_string(compares.size()) + ")");
  }
  for (const QString& text : compares)
    line.compare.push_back(checkedRunSpec(text));
  if (const auto text = single(size)) line.size = parseSize(*text);
  if (const auto text = single(balls)) {
    line.balls = static_cast<std::size_t>(
        parseCount(*text, QStringLiteral("balls"), 0, static_cast<long long>(kMaxBalls)));
  }
  if (const auto text = single(frames)) {
    line.frames = static_cast<int>(parseCount(*text, QStringLiteral("frames"), 1, 1'000'000));
  }
  line.screenshot = single(screenshot);
  if (line.screenshot && line.screenshot->isEmpty())
    throw UsageError("--screenshot: empty file name");
  line.record = single(record);
  if (const auto text = single(fps)) {
    if (!line.record) throw UsageError("--fps: only with --record");
    line.recordFramesPerSecond =
        static_cast<int>(parseCount(*text, QStringLiteral("fps"), 1, 1000));
  }
  line.recordCharts = parser.isSet(recordCharts);
  if (line.recordCharts && !line.record) throw UsageError("--record-charts: only with --record");
  if (line.record) checkRecording(line);
  for (const QString& items : parser.values(show)) {
    for (const QString& item : items.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
      if (!kShowItems.contains(item)) {
        throw UsageError("--show: unknown item '" + item.toStdString() +
                         "' (known: " + kShowItems.join(QStringLiteral(", ")).toStdString() + ")");
      }
      line.show.append(item);
    }
  }
  for (const QString& point : parser.values(attractor)) {
    const QStringList parts = point.split(QLatin1Char(','));
    bool xOk = false;
    bool yOk = false;
    const double x = parts.size() == 2 ? parts[0].toDouble(&xOk) : 0.0;
    const double y = parts.size() == 2 ? parts[1].toDouble(&yOk) : 0.0;
    if (!xOk || !yOk || !std::isfinite(x) || !std::isfinite(y)) {
      throw UsageError("--attractor: expected X,Y in metres (got '" + point.toStdString() + "')");
    }
    line.attractors.push_back({x, y});
  }
  return line;
}

}  // namespace fooball::gui
