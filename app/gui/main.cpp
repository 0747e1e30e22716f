// fooball: the Qt desktop app (DESIGN.md, "fooball (GUI)").

#include <QApplication>
#include <QFileInfo>
#include <QIcon>
#include <QSettings>
#include <cstdlib>
#include <exception>
#include <iostream>

#include "fooball/presets.h"
#include "fooball/scene_error.h"
#include "fooball/scene_file.h"
#include "fooball/version.h"
#include "registry.h"
#include "widgets/dark_theme.h"
#include "widgets/view_text.h"
#include "window/command_line.h"
#include "window/headless_run.h"
#include "window/main_window.h"
#include "window/window_settings.h"

namespace {

using namespace fooball;
using namespace fooball::gui;

constexpr const char* kNoDisplay =
    "fooball: no display found (DISPLAY/WAYLAND_DISPLAY unset). Run the headless simulator "
    "instead: fooball-cli run --preset default\n";

constexpr const char* kDisplayUnusable =
    "fooball: the display could not be used (Qt's message above). Run the headless simulator "
    "instead: fooball-cli run --preset default\n";

/// A window system to connect to, or the user has chosen a Qt platform themselves (an empty
/// QT_QPA_PLATFORM chooses nothing: Qt then tries its default, as without it).
bool displayAvailable() {
  return !qEnvironmentVariableIsEmpty("DISPLAY") ||
         !qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY") ||
         !qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM");
}

QtMessageHandler qtMessageHandler = nullptr;

/// While QApplication starts: Qt gives up with a fatal message when no platform plugin can start
/// (a DISPLAY that no server answers). After its message, say what to run instead and end as
/// for no display at all, rather than abort.
void pointToHeadlessWhenQtGivesUp(QtMsgType type, const QMessageLogContext& context,
                                  const QString& message) {
  if (qtMessageHandler) {
    qtMessageHandler(type, context, message);
  } else {
    std::cerr << qPrintable(qFormatLogMessage(type, context, message)) << '\n';
  }
  if (type == QtFatalMsg) {
    std::cerr << kDisplayUnusable;
    std::_Exit(2);  // mid-construction: no static destructors
  }
}

bool isRegisteredBackend(const std::string& name) {
  for (const BackendInfo& info : registeredBackends()) {
    if (name == info.name) return true;
  }
  return false;
}

/// The command line first, then (for interactive runs) what the user chose last time.
/// Throws SceneError for a bad scene file or an unknown preset named on the command line.
StartupOptions startupOptions(const CommandLine& line, bool remember) {
  StartupOptions options;
  options.rememberSettings = remember;
  QSettings settings;
  if (line.sceneFile) {
    const std::string path = QFile::encodeName(*line.sceneFile).toStdString();
    options.scene = loadSceneFile(path);
    // A state saved from a running simulation that a hand-written file could not hold: said
    // once, on stderr like the errors, and the app starts on it.
    const std::string warning = savedStateWarning(options.scene, path);
    if (!warning.empty()) std::cerr << "fooball: warning: " << warning << '\n';
    options.sourceName = QFileInfo(*line.sceneFile).fileName();
  } else {
    QString name = line.preset.value_or(fromView(kDefaultPreset));
    if (!line.preset && remember) name = settings.value("scene/preset", name).toString();
    try {
      options.scene = loadPreset(name.toStdString());
    } catch (const SceneError&) {
      if (line.preset) throw;
      name = fromView(kDefaultPreset);
      options.scene = loadPreset(kDefaultPreset);
    }
    options.presetName = name;
    options.sourceName = name;
  }
  RunSpec reference{std::string(registeredBackends().front().name), {}};
  if (line.backend) {
    reference = *line.backend;
  } else if (remember) {
    const std::string remembered = settings.value("run/backend").toString().toStdString();
    if (isRegisteredBackend(remembered)) reference.backend = remembered;
  }
  options.runs = {reference};
  options.runs.insert(options.runs.end(), line.compare.begin(), line.compare.end());
  options.balls = line.balls;
  options.show = line.show;
  options.attractors = line.attractors;
  return options;
}

}  // namespace

int main(int argc, char* argv[]) {
  QStringList arguments;
  for (int i = 0; i < argc; ++i)
    arguments << QString::fromLocal8Bit(argv[i]);
  CommandLine line;
  try {
    line = parseCommandLine(arguments);
  } catch (const UsageError& error) {
    std::cerr << "fooball: error: " << error.what() << '\n';
    return 2;
  }
  if (line.help) {
    std::cout << usageText().toStdString();
    return 0;
  }
  if (line.version) {
    std::cout << kVersionLine << '\n';
    return 0;
  }
  if (!displayAvailable()) {
    if (!line.headless()) {
      std::cerr << kNoDisplay;
      return 2;
    }
    qputenv("QT_QPA_PLATFORM", "offscreen");
  }

  QApplication::setOrganizationName(QStringLiteral("FooBall"));
  QApplication::setApplicationName(QStringLiteral("fooball"));
  if (line.resetSettings) forgetWindowSettings();
  // The scene first: a bad file or preset is one line on stderr, before Qt says anything.
  StartupOptions options;
  try {
    options = startupOptions(line, !line.headless());
  } catch (const SceneError& error) {
    std::cerr << "fooball: error: " << error.what() << '\n';
    return 2;
  }

  qtMessageHandler = qInstallMessageHandler(pointToHeadlessWhenQtGivesUp);
  QApplication app(argc, argv);
  qInstallMessageHandler(qtMessageHandler);
  applyDarkTheme(app);
  QApplication::setApplicationDisplayName(QStringLiteral("FooBall"));
  QApplication::setApplicationVersion(fromView(kVersion));
  // The installed icon theme's where there is one; the copy built into the program otherwise
  // (a build tree run, or a desktop without hicolor).
  QApplication::setWindowIcon(
      QIcon::fromTheme(QStringLiteral("fooball"), QIcon(QStringLiteral(":/icons/fooball.png"))));
  QGuiApplication::setDesktopFileName(QStringLiteral("fooball"));
  try {
    MainWindow window(options);
    if (line.record) {
      const RecordingSettings recording{
          *line.record, line.recordCharts ? RecordArea::BoxAndCharts : RecordArea::Box,
          recordingSize(line), line.recordFramesPerSecond};
      return recordHeadless(window, recording, *line.frames, line.screenshot);
    }
    if (line.headless())
      return runHeadless(window, line.frames.value_or(1), line.screenshot, line.size);
    if (line.size) window.resize(*line.size);
    window.show();
    window.startLiveUpdates();
    return QApplication::exec();
  } catch (const SceneError& error) {
    std::cerr << "fooball: error: " << error.what() << '\n';
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "fooball: error: " << error.what() << '\n';
    return 1;
  }
}
