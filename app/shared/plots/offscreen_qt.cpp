#include "offscreen_qt.h"

#include <QApplication>
#include <cstdio>

namespace fooball::plots {

namespace {

/// Keeps Qt's platform chatter ("XDG_RUNTIME_DIR not set", size-hint notes of the offscreen
/// platform) off stderr, which is for the command's own errors; real failures still show.
void quietMessages(QtMsgType type, const QMessageLogContext& context, const QString& message) {
  if (type == QtDebugMsg || type == QtInfoMsg || type == QtWarningMsg) return;
  std::fprintf(stderr, "%s\n", qPrintable(qFormatLogMessage(type, context, message)));
}

// QApplication keeps references to argc and argv for its whole life.
int applicationArgc = 1;
char applicationName[] = "fooball-cli";
char* applicationArgv[] = {applicationName, nullptr};

}  // namespace

OffscreenQt::OffscreenQt() {
  if (QApplication::instance() != nullptr) return;
  if (!qEnvironmentVariableIsSet("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  previousHandler_ = qInstallMessageHandler(quietMessages);
  ownApplication_ = std::make_unique<QApplication>(applicationArgc, applicationArgv);
}

OffscreenQt::~OffscreenQt() {
  if (ownApplication_) qInstallMessageHandler(previousHandler_);
}

}  // namespace fooball::plots
