#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

#include "fooball/backend.h"
#include "fooball/scene.h"

namespace fooball::failure_map {

/// s: the step every sweep runs at, one frame at 60 Hz (the GUI's and `run`'s default).
inline constexpr double kFrameDt = 1.0 / 60.0;

/// s: the time step of `backend`'s solver, `dt` over its substeps (the option of role
/// OptionRole::Substeps) when it has them.
double solverStep(const Backend& backend, double dt);

/// What one run of a scene did, watched after every step.
struct RunRecord {
  double energyDrift = 0.0;      ///< J, largest |E(t) − E(0)| (Metrics::energyResidual)
  double energyError = 0.0;      ///< largest |relativeEnergyError| (fooball/metrics.h)
  double maxOverlap = 0.0;       ///< deepest overlap seen, as a fraction of the smaller radius
  std::size_t escaped = 0;       ///< balls outside the box at the end
  std::vector<Vec2> positions;   ///< m, at the end
  std::vector<Vec2> velocities;  ///< m/s, at the end
};

/// Whether a sweep's runs cap a backend's events per step (Backend::capEventsToFinish) so that
/// every point ends; a sweep whose scenes end at the backends' defaults runs them uncapped.
enum class EventCap { Finishing, Default };

/// Runs `scene` (valid) on a fresh `backend` at its default options for `seconds` (whole steps
/// of `dt`, at least one).
RunRecord runScene(const Scene& scene, std::string_view backend, double seconds,
                   double dt = kFrameDt, EventCap cap = EventCap::Finishing);

/// The i-th of a fixed, well-spread sequence of directions (golden-angle steps), as a unit
/// vector: reproducible "random" velocities without a random generator.
Vec2 spreadDirection(std::size_t i);

/// `count` values from `first` to `last` (both included) evenly spaced in log scale.
std::vector<double> logGrid(double first, double last, std::size_t count);

}  // namespace fooball::failure_map
