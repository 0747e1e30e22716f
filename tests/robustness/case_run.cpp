#include "case_run.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "backend_profiles.h"
#include "fooball/scene_error.h"
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

std::string runCase(const RandomCase& c, const BackendInfo& info, const Tolerances& tolerances,
                    const WorkCap& cap) {
  std::unique_ptr<Backend> backend = info.create();
  for (const auto& [name, value] : c.options)
    backend->setOption(name, value);
  Simulation simulation(c.scene, std::move(backend));
  simulation.setDt(c.dt);
  const bool closed = c.closed();
  const std::size_t count = c.scene.balls.size();
  const double startEnergy = energyAboveBoxMinimum(simulation);
  const double scale = energyScale(simulation);
  WorkMeter meter(cap, count);
  int stepsRun = 0;
  while (stepsRun < c.steps) {
    const int step = stepsRun++;
    apply(c, step, simulation);
    simulation.step();
    if (simulation.ballCount() != count || simulation.backend().ballCount() != count)
      return "the ball count changed at step " + std::to_string(step);
    if (std::string violation = checkState(simulation, closed, tolerances.wallSlack);
        !violation.empty())
      return "at step " + std::to_string(step) + ": " + violation;
    if (!meter.count(simulation)) break;
  }
  const bool checkEnergy =
      c.scene.world.gravity == Vec2{} ||
      (tolerances.energyKeptUnderGravity &&
       (tolerances.energyKeptUnderGravityWithCollisions || !c.scene.world.ballCollisions));
  if (c.isolated() && checkEnergy) {
    const double endEnergy = energyAboveBoxMinimum(simulation);
    const double allowed =
        (1.0 + tolerances.energyRelative) * startEnergy + tolerances.energyAbsolute * scale;
    if (!(endEnergy <= allowed)) {
      std::ostringstream out;
      out.precision(17);
      out << "energy grew from " << startEnergy << " J to " << endEnergy << " J (allowed "
          << allowed << " J, ratio " << endEnergy / startEnergy << ")";
      if (stepsRun < c.steps) out << " in the " << stepsRun << " steps run before the work cap";
      return out.str();
    }
  }
  return "";
}

}  // namespace fooball::robustness
