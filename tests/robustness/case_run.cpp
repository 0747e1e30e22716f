#include "case_run.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <sstream>

#include "backend_profiles.h"
#include "fooball/metrics.h"
#include "fooball/scene_error.h"
#include "fooball/scene_file.h"
#include "fooball/simulation.h"

namespace fooball::robustness {
namespace {

/// J: kinetic energy plus potential energy above the lowest point of the box (the corner
/// furthest along g), so it is ≥ 0 while the balls are inside and "grew by a fraction" means
/// the same whatever the direction of gravity.
double energyAboveBoxMinimum(const Simulation& simulation) {
  const Vec2 g = simulation.world().gravity;
  const Box box = simulation.box();
  const double lowest =
      std::min({0.0, -g.x * box.width, -g.y * box.height, -g.x * box.width - g.y * box.height});
  double energy = 0.0;
  for (std::size_t i = 0; i < simulation.ballCount(); ++i) {
    const double m = simulation.masses()[i];
    energy += 0.5 * m * lengthSquared(simulation.velocities()[i]) +
              m * (-dot(g, simulation.positions()[i]) - lowest);
  }
  return energy;
}

/// J: the scale of the absolute slack: the energy of lifting every ball by the largest radius
/// plus that of moving it at the fastest speed.
double energyScale(const Simulation& simulation) {
  double maxRadius = 0.0;
  double maxSpeedSquared = 0.0;
  double mass = 0.0;
  for (std::size_t i = 0; i < simulation.ballCount(); ++i) {
    maxRadius = std::max(maxRadius, simulation.radii()[i]);
    maxSpeedSquared = std::max(maxSpeedSquared, lengthSquared(simulation.velocities()[i]));
    mass += simulation.masses()[i];
  }
  return mass * (length(simulation.world().gravity) * maxRadius + maxSpeedSquared);
}

std::string checkState(const Simulation& simulation, bool closed, double slack) {
  const Box box = simulation.box();
  for (std::size_t i = 0; i < simulation.ballCount(); ++i) {
    const Vec2 p = simulation.positions()[i];
    const Vec2 v = simulation.velocities()[i];
    std::ostringstream out;
    out.precision(17);
    if (!isFinite(p) || !isFinite(v)) {
      out << "ball " << i << " is not finite: position (" << p.x << ", " << p.y << "), velocity ("
          << v.x << ", " << v.y << ")";
      return out.str();
    }
    // The contract keeps every centre in the box: a ball may sink into a wall by up to its
    // radius (time-stepped solvers resolve a wall contact after the ball has crossed it), never
    // further, give or take the backend's slack.
    if (closed && !(p.x >= -slack && p.x <= box.width + slack && p.y >= -slack &&
                    p.y <= box.height + slack)) {
      out << "ball " << i << " (radius " << simulation.radii()[i] << ") left the closed box: at ("
          << p.x << ", " << p.y << "), velocity (" << v.x << ", " << v.y << ")";
      return out.str();
    }
  }
  return "";
}

/// The work a backend has done in a run, counted as its WorkCap says.
class WorkMeter {
 public:
  WorkMeter(const WorkCap& cap, std::size_t balls)
      : cap_(cap), weight_(cap.perBall ? static_cast<double>(balls + 1) : 1.0) {}

  /// Adds the work of the step just taken; true while the cap is not passed.
  bool count(const Simulation& simulation) {
    if (cap_.counter.empty()) return true;
    for (const Diagnostic& diagnostic : simulation.backend().diagnostics()) {
      if (diagnostic.name != cap_.counter) continue;
      // A reload (setBall may reload) restarts the backend's count.
      const double done =
          diagnostic.value >= counted_ ? diagnostic.value - counted_ : diagnostic.value;
      work_ += weight_ * done;
      counted_ = diagnostic.value;
    }
    return work_ <= cap_.max;
  }

 private:
  WorkCap cap_;
  double weight_;
  double counted_ = 0.0;  ///< the counter's value after the last step
  double work_ = 0.0;
};

/// The deepest overlap of a ball with a wall (every wall is on in a closed case), less `slack`
/// (m), as a fraction of the ball's radius.
double deepestWallOverlap(const Simulation& simulation, double slack) {
  const Box box = simulation.box();
  double deepest = 0.0;
  for (std::size_t i = 0; i < simulation.ballCount(); ++i) {
    const Vec2 p = simulation.positions()[i];
    const double r = simulation.radii()[i];
    const double nearestWall = std::min({p.x, box.width - p.x, p.y, box.height - p.y});
    deepest = std::max(deepest, (r - nearestWall - slack) / r);
  }
  return deepest;
}

/// Ball collisions on from the start to the end: every overlap is the method's to resolve.
bool collisionsStayOn(const RandomCase& c) {
  return c.scene.world.ballCollisions &&
         std::all_of(c.worldChanges.begin(), c.worldChanges.end(),
                     [](const WorldChange& change) { return change.world.ballCollisions; });
}

EnergyWorld energyWorldOf(const RandomCase& c) {
  if (!c.isolated()) return EnergyWorld::None;
  if (c.scene.world.gravity == Vec2{}) return EnergyWorld::WithoutGravity;
  if (!c.closed()) return EnergyWorld::UnderGravityOpen;
  return c.scene.world.ballCollisions ? EnergyWorld::UnderGravityWithCollisions
                                      : EnergyWorld::UnderGravity;
}

/// The value of the backend's diagnostics entry `name` (0 when it has none).
double diagnostic(const Simulation& simulation, std::string_view name) {
  for (const Diagnostic& entry : simulation.backend().diagnostics()) {
    if (entry.name == name) return entry.value;
  }
  return 0.0;
}

/// Whether every ball travels at most `limit` of the smallest radius in one substep: the
/// fastest speed × dt / substeps (substeps: the option of role OptionRole::Substeps, 1 for a
/// backend without one; options that raise it further only shorten the travel).
bool resolved(const Simulation& simulation, double limit) {
  if (simulation.ballCount() == 0 || limit == std::numeric_limits<double>::infinity()) return true;
  const OptionSet& options = simulation.backend().options();
  const OptionSpec* substeps = options.withRole(OptionRole::Substeps);
  const double substep = simulation.dt() / (substeps ? options.value(substeps->name) : 1.0);
  double fastest = 0.0;
  for (const Vec2 v : simulation.velocities())
    fastest = std::max(fastest, length(v));
  const double smallest = *std::min_element(simulation.radii().begin(), simulation.radii().end());
  return fastest * substep <= limit * smallest;
}

/// Counts the steps in which a cumulative diagnostics counter rose (none for the name "").
/// Whether the run's count of steps cut short (BackendCounters::cutShortSteps: steps the method
/// advanced without resolving every contact, by design) rose in the step just taken.
class CutShortSteps {
 public:
  /// A reload (setBall may reload) restarts the backend's count, so a lower value is a count
  /// afresh.
  bool rose(const Simulation& simulation) {
    const std::uint64_t value = simulation.counters().cutShortSteps;
    const bool rose = value > (value >= last_ ? last_ : 0u);
    last_ = value;
    return rose;
  }

 private:
  std::uint64_t last_ = 0;
};

std::uint64_t bitsOf(double value) {
  return std::bit_cast<std::uint64_t>(value);
}

/// How `reopened` differs from `saved`, bit for bit (-0.0 is not 0.0), or "".
std::string differenceOf(const Scene& saved, const Scene& reopened) {
  if (reopened.name != saved.name || reopened.box != saved.box || reopened.world != saved.world ||
      reopened.savedFrom != saved.savedFrom) {
    return "its name, box, world or saved_from changed";
  }
  if (reopened.balls.size() != saved.balls.size()) return "its ball count changed";
  for (std::size_t i = 0; i < saved.balls.size(); ++i) {
    const BallDef& a = saved.balls[i];
    const BallDef& b = reopened.balls[i];
    const bool same = bitsOf(a.position.x) == bitsOf(b.position.x) &&
                      bitsOf(a.position.y) == bitsOf(b.position.y) &&
                      bitsOf(a.velocity.x) == bitsOf(b.velocity.x) &&
                      bitsOf(a.velocity.y) == bitsOf(b.velocity.y) &&
                      bitsOf(a.radius) == bitsOf(b.radius) && bitsOf(a.mass) == bitsOf(b.mass) &&
                      a.color == b.color;
    if (!same) return "balls[" + std::to_string(i) + "] changed";
  }
  return "";
}

/// The state now, saved as File → Save writes it, reopened: "" when it comes back bit for bit.
std::string reopenSavedState(const Simulation& simulation, std::string_view backend) {
  const Scene saved = simulation.savedScene(backend);
  try {
    const std::string difference = differenceOf(saved, parseScene(writeScene(saved), "saved"));
    return difference.empty() ? "" : "the saved state reopened, but " + difference;
  } catch (const SceneError& error) {
    return std::string("the saved state does not reopen: ") + error.what();
  }
}

void apply(const RandomCase& c, int step, Simulation& simulation) {
  for (const WorldChange& change : c.worldChanges) {
    if (change.step == step) simulation.setWorld(change.world);
  }
  for (const BallEdit& edit : c.edits) {
    if (edit.step != step) continue;
    BallDef ball = simulation.scene().balls[edit.index];
    ball.velocity = edit.velocity;
    ball.radius *= edit.radiusScale;
    ball.mass = edit.mass;
    try {
      simulation.setBall(edit.index, ball);
    } catch (const SceneError&) {
      // The ball sits deeper in a wall or another ball than a valid scene allows (solvers leave
      // contacts up to their slop); the driver refuses the edit, as the GUI's inspector would.
    }
  }
  for (const ToolUse& tool : c.tools) {
    Interactions& interactions = simulation.interactions;
    if (tool.start == step) {
      interactions.mode = tool.mode;
      interactions.scope = tool.scope;
      interactions.strength = tool.strength;
      interactions.press(tool.point, simulation.balls());
    } else if (tool.start + tool.duration == step && interactions.pressed()) {
      interactions.release(tool.point);
    }
  }
}

}  // namespace

Tolerances tolerancesFor(std::string_view backend) {
  return testing::profileFor(backend).robustness;
}

WorkCap workCapFor(std::string_view backend) {
  return testing::profileFor(backend).workCap;
}

CaseOutcome runCase(const RandomCase& c, const BackendInfo& info, const Tolerances& tolerances,
                    const WorkCap& cap) {
  std::unique_ptr<Backend> backend = info.create();
  for (const auto& [name, value] : c.options)
    backend->setOption(name, value);
  Simulation simulation(c.scene, std::move(backend));
  simulation.setDt(c.dt);
  const bool closed = c.closed();
  const bool collisionsOn = collisionsStayOn(c);
  const std::size_t count = c.scene.balls.size();
  CaseOutcome outcome;
  outcome.isolated = c.isolated();
  outcome.energyWorld = energyWorldOf(c);
  outcome.startEnergy = energyAboveBoxMinimum(simulation);
  outcome.energyScale = energyScale(simulation);
  WorkMeter meter(cap, count);
  CutShortSteps cutShortSteps;
  bool resolvedSoFar = resolved(simulation, tolerances.resolvedTravel);
  while (outcome.stepsRun < c.steps) {
    const int step = outcome.stepsRun++;
    apply(c, step, simulation);
    simulation.step();
    if (simulation.ballCount() != count || simulation.backend().ballCount() != count) {
      outcome.stepViolation = "the ball count changed at step " + std::to_string(step);
      return outcome;
    }
    if (std::string violation = checkState(simulation, closed, tolerances.wallSlack);
        !violation.empty()) {
      outcome.stepViolation = "at step " + std::to_string(step) + ": " + violation;
      return outcome;
    }
    resolvedSoFar = resolvedSoFar && !cutShortSteps.rose(simulation) &&
                    resolved(simulation, tolerances.resolvedTravel);
    if (resolvedSoFar) {
      ++outcome.resolvedSteps;
      if (collisionsOn) {
        const double overlap = maxOverlap(simulation.positions(), simulation.radii(),
                                          simulation.box(), Walls{false, false, false, false});
        if (overlap > outcome.ballOverlap || outcome.ballOverlapStep < 0) {
          outcome.ballOverlap = overlap;
          outcome.ballOverlapStep = step;
        }
      }
      if (closed) {
        const double overlap = deepestWallOverlap(simulation, tolerances.wallSlack);
        if (overlap > outcome.wallOverlap || outcome.wallOverlapStep < 0) {
          outcome.wallOverlap = overlap;
          outcome.wallOverlapStep = step;
        }
      }
    }
    if (!meter.count(simulation)) {
      outcome.stoppedByWorkCap = outcome.stepsRun < c.steps;
      break;
    }
  }
  outcome.endEnergy = energyAboveBoxMinimum(simulation);
  if (!tolerances.reportedEnergyChange.empty())
    outcome.reportedEnergyChange = diagnostic(simulation, tolerances.reportedEnergyChange);
  outcome.reopenError = reopenSavedState(simulation, info.name);
  return outcome;
}

std::string violationOf(const CaseOutcome& outcome, const Tolerances& tolerances) {
  if (!outcome.stepViolation.empty()) return outcome.stepViolation;
  std::ostringstream out;
  out.precision(17);
  const char* cut = outcome.stoppedByWorkCap ? " (in the steps run before the work cap)" : "";
  const testing::Interval* energy = nullptr;
  switch (outcome.energyWorld) {
    case EnergyWorld::None:
      break;
    case EnergyWorld::WithoutGravity:
      energy = &tolerances.energyWithoutGravity;
      break;
    case EnergyWorld::UnderGravity:
      energy = &tolerances.energyUnderGravity;
      break;
    case EnergyWorld::UnderGravityWithCollisions:
      energy = &tolerances.energyUnderGravityWithCollisions;
      break;
    case EnergyWorld::UnderGravityOpen:
      energy = &tolerances.energyUnderGravityOpen;
      break;
  }
  if (energy != nullptr) {
    const double change = outcome.endEnergy - outcome.startEnergy - outcome.reportedEnergyChange;
    const double slack = tolerances.energyAbsolute * outcome.energyScale;
    const double low = energy->low * outcome.startEnergy - slack;
    const double high = energy->high * outcome.startEnergy + slack;
    if (!(change >= low && change <= high)) {
      out << "energy " << (change > 0.0 ? "grew" : "fell") << " from " << outcome.startEnergy
          << " J to " << outcome.endEnergy << " J, " << outcome.reportedEnergyChange
          << " J of it reported by the method (relative change " << outcome.relativeEnergyChange()
          << ", allowed " << energy->low << " to " << energy->high << " of it, ±" << slack << " J)"
          << cut;
      return out.str();
    }
  }
  const double ballOverlap =
      outcome.isolated ? tolerances.ballOverlap : tolerances.ballOverlapWithInteractions;
  if (outcome.ballOverlap > ballOverlap) {
    out << "balls overlapped by " << outcome.ballOverlap << " of the smaller radius at step "
        << outcome.ballOverlapStep << " (allowed " << ballOverlap
        << (outcome.isolated ? " in an isolated case)" : " with interactions)");
    return out.str();
  }
  if (outcome.wallOverlap > tolerances.wallOverlap) {
    out << "a ball overlapped a wall by " << outcome.wallOverlap << " of its radius beyond the "
        << tolerances.wallSlack << " m slack at step " << outcome.wallOverlapStep << " (allowed "
        << tolerances.wallOverlap << ")";
    return out.str();
  }
  return outcome.reopenError;
}

}  // namespace fooball::robustness
