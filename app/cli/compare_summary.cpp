#include "compare_summary.h"

#include <algorithm>
#include <cmath>

#include "readable_number.h"
#include "text_table.h"

namespace fooball::cli {

namespace {

/// `change` relative to `scale`, or absolute (in `unit`) when there is no scale to divide by,
/// e.g. a scene at rest or with zero total energy.
std::string changeText(double change, double scale, const std::string& unit) {
  if (scale > 0.0) return text::readableText(change / scale, 3);
  return text::readableText(change, 3) + " " + unit;
}

/// The relative energy error (fooball/metrics.h), or "-" where E(0) is 0.
std::string energyErrorText(const Metrics& metrics) {
  const double error = relativeEnergyError(metrics);
  return std::isnan(error) ? "-" : text::readableText(error, 3);
}

std::string stepsPerSecondText(std::uint64_t steps, double seconds) {
  if (!(seconds > 0.0)) return "-";
  return std::to_string(std::llround(static_cast<double>(steps) / seconds));
}

}  // namespace

void printCompareSummary(const CompareSummary& summary, std::ostream& out) {
  const std::string scene = summary.sceneName.empty()
                                ? summary.sceneSource
                                : "'" + summary.sceneName + "' (" + summary.sceneSource + ")";
  const ComparedRun& reference = summary.runs.front();
  out << "Compare on " << scene << ": " << summary.balls << " balls, " << summary.steps
      << " steps of dt " << text::readableText(summary.dt)
      << " s to t = " << text::readableText(reference.end.time)
      << " s, every run from the same state in lockstep.\n"
      << "Divergence: RMS distance from run 0 (" << reference.label
      << ") over balls of the same index. Energy change relative to |E(0)|; energy error: the "
         "energy "
         "budget's residual (the method's own error) relative to |E(0)|; momentum change "
         "relative to max(|P(0)|, sum m|v|).\n\n";

  TextTable table;
  table.addRow({"run", "steps/s", "energy change", "energy error", "momentum change",
                "RMS divergence (m)", "departs at"});
  for (std::size_t i = 0; i < summary.runs.size(); ++i) {
    const ComparedRun& run = summary.runs[i];
    const double startEnergy = run.start.sums.totalEnergy();
    const double energyChange = run.end.sums.totalEnergy() - startEnergy;
    const double momentumChange = length(run.end.sums.momentum - run.start.sums.momentum);
    // A scene whose total momentum is ~0 (a gas) still has a momentum scale: Σ m|v|.
    const double momentumScale = std::max(length(run.start.sums.momentum), run.startSpeedMomentum);
    const std::string departs =
        i == 0 ? "reference"
               : (run.departedAt ? text::readableText(*run.departedAt, 4) + " s" : "never");
    table.addRow({run.label, stepsPerSecondText(summary.steps, run.steppingSeconds),
                  changeText(energyChange, std::abs(startEnergy), "J"), energyErrorText(run.end),
                  changeText(momentumChange, momentumScale, "N s"),
                  i == 0 ? "0" : text::readableText(run.rmsDivergence, 3), departs});
  }
  table.print(out, 2);
  out << "\ndeparts at: when the RMS divergence first exceeds 10% of the mean radius ("
      << text::readableText(summary.departThreshold, 3)
      << " m), checked every step; never: not by t = " << text::readableText(reference.end.time)
      << " s.\n";
  if (summary.hasBaseline) {
    out << "baseline: run 0 (" << reference.label << ") with every ball moved "
        << text::readableText(summary.baselineDisplacement)
        << " m in a random direction. It shows how fast this scene amplifies any difference: a "
           "run that departs no sooner than the baseline is as close to run 0 as chaos allows.\n";
  }
}

}  // namespace fooball::cli
