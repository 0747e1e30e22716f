#pragma once

#include <gtest/gtest.h>

#include <QProcess>
#include <QProcessEnvironment>
#include <QString>
#include <QStringList>
#include <utility>
#include <vector>

#include "program_path.h"

namespace fooball::gui::testing {

/// What a run of the fooball binary gave.
struct Outcome {
  int exitCode = -1;
  QString out;
  QString err;
};

using Variables = std::vector<std::pair<QString, QString>>;
inline const Variables kOffscreen = {
    {QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen")}};

/// Runs the built fooball binary with no display at all, as CI does, and `variables` set.
inline Outcome runFooball(const QStringList& arguments, const Variables& variables = {},
                          int timeoutMs = 60'000) {
  QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
  environment.remove(QStringLiteral("DISPLAY"));
  environment.remove(QStringLiteral("WAYLAND_DISPLAY"));
  environment.remove(QStringLiteral("QT_QPA_PLATFORM"));
  for (const auto& [name, value] : variables)
    environment.insert(name, value);
  QProcess process;
  process.setProcessEnvironment(environment);
  process.start(QString::fromUtf8(checkout::kGuiPath), arguments);
  EXPECT_TRUE(process.waitForFinished(timeoutMs));
  return {process.exitCode(), QString::fromLocal8Bit(process.readAllStandardOutput()),
          QString::fromLocal8Bit(process.readAllStandardError())};
}

}  // namespace fooball::gui::testing
