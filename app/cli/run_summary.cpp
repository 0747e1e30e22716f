#include "run_summary.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "readable_number.h"
#include "text_table.h"

namespace fooball::cli {

namespace {

/// `change` relative to `scale`, or absolute (in `unit`) when there is no scale to divide by,
/// e.g. a scene at rest or with zero total energy.
std::string changeText(double change, double scale, const std::string& unit) {
  if (scale > 0.0) return text::readableText(change / scale) + " (relative)";
  return text::readableText(change) + " " + unit + " (absolute)";
}

/// The relative energy error (fooball/metrics.h), or why there is none.
std::string energyErrorText(const Metrics& metrics) {
  const double error = relativeEnergyError(metrics);
  if (std::isnan(error)) return "none (E(0) = 0: see the residual)";
  return text::readableText(error) + " (residual / |E(0)|)";
}

std::string backendText(const RunSummary& summary) {
  if (summary.changedOptions.empty()) return summary.backendName;
  std::string text = summary.backendName + " (";
  for (std::size_t i = 0; i < summary.changedOptions.size(); ++i) {
    text += (i == 0 ? "" : ", ") + summary.changedOptions[i];
  }
  return text + ")";
}

}  // namespace

void printRunSummary(const RunSummary& summary, std::ostream& out) {
  const double startEnergy = summary.start.sums.totalEnergy();
  const double energyChange = summary.end.sums.totalEnergy() - startEnergy;
  const double momentumChange = length(summary.end.sums.momentum - summary.start.sums.momentum);
  // A scene whose total momentum is ~0 (a gas) still has a momentum scale: Σ m|v|.
  const double momentumScale =
      std::max(length(summary.start.sums.momentum), summary.startSpeedMomentum);
  const double stepsPerSecond = summary.physicsSeconds > 0.0
                                    ? static_cast<double>(summary.steps) / summary.physicsSeconds
                                    : 0.0;

  const std::string sceneText = summary.sceneName.empty()
                                    ? summary.sceneSource
                                    : summary.sceneName + " (" + summary.sceneSource + ")";

  TextTable table;
  table.addRow({"scene:", sceneText});
  table.addRow({"backend:", backendText(summary)});
  table.addRow({"balls:", std::to_string(summary.balls)});
  table.addRow({"steps:", std::to_string(summary.steps)});
  table.addRow({"dt:", text::readableText(summary.dt) + " s"});
  table.addRow({"simulated time:", text::readableText(summary.end.time) + " s"});
  table.addRow({"wall-clock:", text::readableText(summary.wallSeconds, 4) + " s (physics " +
                                   text::readableText(summary.physicsSeconds, 4) + " s)"});
  table.addRow({"steps/s:", std::to_string(std::llround(stepsPerSecond)) + " (physics)"});
  table.addRow({"energy change:", changeText(energyChange, std::abs(startEnergy), "J")});
  table.addRow({"momentum change:", changeText(momentumChange, momentumScale, "N s")});
  table.addRow({"energy residual:", text::readableText(summary.end.energyResidual) + " J"});
  table.addRow({"energy error:", energyErrorText(summary.end)});
  if (summary.end.restingBalls != 0 || summary.end.restEnergyChange != 0.0) {
    // A method's resting rule is active: what it holds still, and the energy it booked.
    table.addRow({"resting balls:", std::to_string(summary.end.restingBalls)});
    table.addRow({"rest energy change:", text::readableText(summary.end.restEnergyChange) +
                                             " J (booked, out of the residual)"});
  }
  table.addRow({"ball collisions:", std::to_string(summary.end.ballCollisions)});
  table.addRow({"wall collisions:", std::to_string(summary.end.wallCollisions)});
  for (const Diagnostic& diagnostic : summary.diagnostics) {
    table.addRow({diagnostic.name + ":", text::readableText(diagnostic.value)});
  }
  table.print(out);
}

}  // namespace fooball::cli
