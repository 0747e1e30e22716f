#include "failure_map.h"

#include <array>
#include <limits>
#include <stdexcept>
#include <string>

#include "sweeps.h"

namespace fooball::failure_map {

namespace {

constexpr double kUnchecked = std::numeric_limits<double>::infinity();

const std::array<SweepSpec, 6> kSweeps = {{
    {"tunnelling", "a ball shot at a resting ball or at a wall",
     "v·h / r (solver step travel in radii)",
     "|Δv| / v0 of the outgoing velocities (2: passed through)", 1e-3, kUnchecked, true, true,
     &tunnellingSweep},
    {"mass-ratio", "head-on hit between masses M and m", "M / m",
     "largest |v' − v'exact| / v0 of the two balls", 1e-3, kUnchecked, true, true, &massRatioSweep},
    {"cradle", "Newton's cradle of five balls, the first shot at the rest",
     "gap / r between resting balls (touching drawn at 1e-5)",
     "|v_last − v0| / v0 + Σ others |v| / v0", 1e-3, kUnchecked, false, true, &cradleSweep},
    {"packing", "gas on a triangular lattice for 2 s (--quick: 1 s)", "packing fraction of the box",
     "largest |E(t) − E(0)| / E(0)", 1e-3, 0.1, true, false, &packingSweep},
    {"scale", "one gas scaled in size and speed for 2 s (--quick: 1 s)",
     "scale s (radii 0.2–0.4·s m; speeds 1–3·s m/s)", "largest |E(t) − E(0)| / E(0)", 1e-3, 0.1,
     true, true, &scaleSweep},
    {"pile", "22 elastic balls resting in a pile for 2 s (--quick: 1 s)", "gravity g (m/s²)",
     "largest |E(t) − E(0)| / Σ m·g·r", 0.1, 0.1, true, true, &pileSweep},
}};

}  // namespace

std::span<const SweepSpec> sweepSpecs() {
  return kSweeps;
}

const SweepSpec& findSweep(std::string_view name) {
  std::string known;
  for (const SweepSpec& spec : kSweeps) {
    if (spec.name == name) return spec;
    known += (known.empty() ? "" : ", ") + std::string(spec.name);
  }
  throw std::invalid_argument("--sweep: unknown sweep '" + std::string(name) +
                              "' (known: " + known + ")");
}

std::vector<SweepPoint> runSweep(const SweepSpec& spec, std::string_view backend, bool quick) {
  std::vector<SweepPoint> points = spec.run(backend, quick);
  for (SweepPoint& point : points) {
    point.sweep = spec.name;
    point.backend = backend;
    // Written so that a NaN error or overlap fails.
    point.passed = point.error <= spec.threshold && point.maxOverlap <= spec.overlapLimit;
  }
  return points;
}

std::vector<SweepPoint> runFailureMap(
    std::span<const SweepSpec* const> sweeps, std::span<const BackendInfo> backends, bool quick,
    const std::function<void(const FailureMapProgress&)>& progress, std::stop_token stop) {
  std::vector<SweepPoint> all;
  const double total = static_cast<double>(sweeps.size() * backends.size());
  double done = 0.0;
  for (const SweepSpec* spec : sweeps) {
    for (const BackendInfo& backend : backends) {
      if (stop.stop_requested()) return all;
      if (progress) progress({spec, backend.name, done / total});
      const std::vector<SweepPoint> own = runSweep(*spec, backend.name, quick);
      all.insert(all.end(), own.begin(), own.end());
      done += 1.0;
    }
  }
  return all;
}

}  // namespace fooball::failure_map
