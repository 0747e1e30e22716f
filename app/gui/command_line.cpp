#include "command_line.h"

#include <QCommandLineParser>
#include <cmath>
#include <string>

#include "fooball/scene.h"
#include "registry.h"

namespace fooball::gui {

namespace {

const QStringList kShowItems{QStringLiteral("temperature"), QStringLiteral("vectors"),
                             QStringLiteral("centre-of-mass"), QStringLiteral("side-by-side")};

void checkBackend(const QString& name) {
  try {
    createBackend(name.toStdString());
  } catch (const std::invalid_argument& error) {
    throw UsageError(error.what());
  }
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

}  // namespace

QString usageText() {
  return QStringLiteral(
      "Usage: fooball [--scene FILE | --preset NAME] [--backend NAME] [--compare NAME]\n"
      "               [--balls N] [--show ITEM,...] [--attractor X,Y]...\n"
      "               [--frames N] [--screenshot FILE.png]\n"
      "\n"
      "FooBall: bouncing balls on interchangeable physics backends, side by side.\n"
      "\n"
      "  --scene FILE       open a scene file (JSON)\n"
      "  --preset NAME      start on a built-in scene (fooball-cli list shows them)\n"
      "  --backend NAME     physics backend of the main run\n"
      "  --compare NAME     start in compare mode with a second backend\n"
      "  --balls N          add or remove balls after loading, like the ball spinner\n"
      "  --show ITEM,...    turn on drawing options: temperature, vectors, centre-of-mass,\n"
      "                     side-by-side (compare layout)\n"
      "  --attractor X,Y    place a permanent attractor at (X, Y) metres (repeatable)\n"
      "  --frames N         run N frames (physics for 1/60 s + drawing each), print the mean\n"
      "                     frame time in ms and exit; works without a display\n"
      "  --screenshot FILE  after the frames, save the window as PNG\n"
      "  -h, --help         show this help\n");
}

CommandLine parseCommandLine(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
  const QCommandLineOption scene(QStringLiteral("scene"), QString(), QStringLiteral("FILE"));
  const QCommandLineOption preset(QStringLiteral("preset"), QString(), QStringLiteral("NAME"));
  const QCommandLineOption backend(QStringLiteral("backend"), QString(), QStringLiteral("NAME"));
  const QCommandLineOption compare(QStringLiteral("compare"), QString(), QStringLiteral("NAME"));
  const QCommandLineOption balls(QStringLiteral("balls"), QString(), QStringLiteral("N"));
  const QCommandLineOption frames(QStringLiteral("frames"), QString(), QStringLiteral("N"));
  const QCommandLineOption screenshot(QStringLiteral("screenshot"), QString(),
                                      QStringLiteral("FILE"));
  const QCommandLineOption show(QStringLiteral("show"), QString(), QStringLiteral("ITEMS"));
  const QCommandLineOption attractor(QStringLiteral("attractor"), QString(), QStringLiteral("X,Y"));
  const QCommandLineOption help(QStringList{QStringLiteral("h"), QStringLiteral("help")});
  parser.addOptions(
      {scene, preset, backend, compare, balls, frames, screenshot, show, attractor, help});

  if (!parser.parse(arguments)) throw UsageError(parser.errorText().toStdString());
  if (!parser.positionalArguments().isEmpty()) {
    throw UsageError("unexpected argument '" + parser.positionalArguments().front().toStdString() +
                     "' (see --help)");
  }

  CommandLine line;
  line.help = parser.isSet(help);
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
  line.backend = single(backend);
  if (line.backend) checkBackend(*line.backend);
  line.compare = single(compare);
  if (line.compare) checkBackend(*line.compare);
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
