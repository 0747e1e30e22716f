#include "random_case.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "fooball/random_balls.h"
#include "fooball/scene_error.h"
#include "fooball/split_mix64.h"

namespace fooball::robustness {
namespace {

/// Uniform draws on the engine's SplitMix64, whose numbers come from integer steps only, so a
/// seed gives the same case with every standard library (std:: distributions are
/// implementation-defined).
class Draw {
 public:
  explicit Draw(std::uint64_t seed) : generator_(seed) {}

  std::uint64_t next() { return generator_.next(); }
  /// [0, 1)
  double unit() { return generator_.unit(); }
  double uniform(double low, double high) { return generator_.between(low, high); }
  /// Uniform in log: every decade between `low` and `high` (both > 0) equally likely.
  double logUniform(double low, double high) {
    return low * std::exp(std::log(high / low) * unit());
  }
  /// [low, high]
  int integer(int low, int high) {
    return low + static_cast<int>(next() % static_cast<std::uint64_t>(high - low + 1));
  }
  /// [low, high], log-uniform: k = low − 1 + j with j = 1, 2, … drawn with probability
  /// ln(1 + 1/j) / ln(high − low + 2), so every decade of j is equally likely (for [1, 200]:
  /// 1 one time in 8, 100 or more one in 8).
  int logInteger(int low, int high) {
    const double j = logUniform(1.0, static_cast<double>(high - low) + 2.0);
    return std::min(high, low - 1 + static_cast<int>(j));
  }
  bool chance(double probability) { return unit() < probability; }
  Vec2 direction() {
    const double angle = uniform(0.0, 2.0 * std::numbers::pi);
    return {std::cos(angle), std::sin(angle)};
  }

 private:
  SplitMix64 generator_;
};

/// m/s²: off, straight down, or any direction, up to 100 g.
Vec2 drawGravity(Draw& draw) {
  if (draw.chance(0.3)) return {};
  const double magnitude = draw.logUniform(0.1, 1000.0);
  return draw.chance(0.5) ? Vec2{0.0, -magnitude} : magnitude * draw.direction();
}

/// 1/s: mostly none; otherwise from barely felt to stopping a ball in 0.1 s.
double drawDrag(Draw& draw) {
  return draw.chance(0.7) ? 0.0 : draw.logUniform(0.01, 10.0);
}

Walls drawWalls(Draw& draw) {
  if (draw.chance(0.7)) return {};
  return {draw.chance(0.5), draw.chance(0.5), draw.chance(0.5), draw.chance(0.5)};
}

WorldSettings drawWorld(Draw& draw) {
  WorldSettings world;
  world.gravity = drawGravity(draw);
  world.airResistance = drawDrag(draw);
  world.ballCollisions = draw.chance(0.8);
  world.walls = drawWalls(draw);
  return world;
}

/// Adds `count` balls of one size class, halving the count until they fit in the space left.
void addBallGroup(Scene& scene, Draw& draw, std::size_t count, double minRadius, double maxRadius,
                  double maxSpeed) {
  RandomBalls spec;
  spec.minRadius = minRadius;
  spec.maxRadius = maxRadius;
  spec.minSpeed = 0.0;
  spec.maxSpeed = maxSpeed;
  spec.seed = draw.next();
  for (spec.count = count; spec.count > 0; spec.count /= 2) {
    try {
      addRandomBalls(scene, spec);
      return;
    } catch (const SceneError&) {
      // Too many for the space left: try half as many.
    }
  }
}

/// 0–200 balls, the count log-uniform (most cases are small and cheap; one in eight has 100 or
/// more). Two size classes (the small one down to 1/100 of the big one), so tiny balls meet big
/// ones; masses spread over six decades around the disk mass, so light balls are struck by
/// heavy ones.
void drawBalls(Scene& scene, Draw& draw) {
  const double side = std::min(scene.box.width, scene.box.height);
  const std::size_t count =
      draw.chance(0.05) ? 0 : static_cast<std::size_t>(draw.logInteger(1, 200));
  const double bigRadius = draw.logUniform(side / 400.0, side / 8.0);
  const double smallRadius = bigRadius * draw.logUniform(0.01, 1.0);
  // m/s: up to 5 box sides per second, so a ball can cross the box in a few steps (faster
  // costs Box2D up to 1000 substeps a step for little more coverage).
  const double maxSpeed = side * draw.logUniform(0.01, 5.0);
  const auto bigCount =
      static_cast<std::size_t>(draw.uniform(0.0, 1.0) * static_cast<double>(count));
  addBallGroup(scene, draw, bigCount, 0.5 * bigRadius, bigRadius, maxSpeed);
  addBallGroup(scene, draw, count - bigCount, 0.5 * smallRadius, smallRadius, maxSpeed);
  if (draw.chance(0.5)) {
    for (BallDef& ball : scene.balls)
      ball.mass *= draw.logUniform(1e-3, 1e3);
  }
}

/// A third of the time each option keeps its default. Otherwise integer options (substeps,
/// iterations, threads) go from their minimum up to 15 above it, log-uniform (the minimum about
/// as often as 8–15 above it), which covers the useful range of counts while bounding the cost;
/// switches (0/1) are even odds; other options go anywhere in their range. Options of role
/// OptionRole::BallsPerThread are 0.
std::vector<std::pair<std::string, double>> drawOptions(Draw& draw,
                                                        std::span<const OptionSpec> specs) {
  std::vector<std::pair<std::string, double>> values;
  for (const OptionSpec& spec : specs) {
    // A case must end: where a backend's default is no cap on a step's work, the case keeps
    // one, drawn from 1, or kFinishingEventsPerBall (Backend::capEventsToFinish).
    const bool keepsACap = spec.role == OptionRole::EventCap;
    const double lowest = keepsACap ? 1.0 : spec.min;
    double value = keepsACap ? kFinishingEventsPerBall : spec.defaultValue;
    if (spec.role == OptionRole::BallsPerThread) {
      // Every drawn thread works: at its default a case of a few hundred balls would always
      // step on one. Not drawn, so the other draws stay those of the pinned findings.
      value = 0.0;
    } else if (draw.chance(2.0 / 3.0)) {
      const int span = static_cast<int>(std::min(spec.max - lowest, 15.0));
      value = !spec.integer ? draw.uniform(lowest, spec.max)
              : span <= 1   ? lowest + static_cast<double>(draw.integer(0, span))
                            : lowest + static_cast<double>(draw.logInteger(0, span));
    }
    values.emplace_back(spec.name, value);
  }
  return values;
}

/// The longest run: 400 steps, fewer when a step is dear. A case costs about (balls + c) ×
/// steps × the options that repeat a step's work: substeps and worker threads (the options of
/// roles OptionRole::Substeps and OptionRole::Threads). Each worker
/// thread beyond the first adds a barrier wait to every phase of a substep: ~15 µs on an idle
/// two-core machine, but up to a scheduler time slice when another process holds the other
/// core (as under ctest -j2, where the elastic suite took 50 s instead of 5 s), so each counts as
/// 16 substeps. A case may have at most 20'000 ball-steps and 1'600 steps × substeps × (1 +
/// 16 × (threads − 1)) (400 steps at the default 4 substeps and one thread). With the steps drawn
/// log-uniform below that, a case costs ~5 ms on average (the median well under 1 ms) and the
/// default 2'000 fit the suite's budget (random_invariants_test.cpp), while long runs (few balls
/// and substeps) and large ones (shorter) stay in the draw: of the default cases 12% have 100
/// balls or more and 4–9% (by backend) 200 steps or more. Box2D's and the exact solver's cost
/// also grows with what happens in the run; their work caps (tests/backend_profiles.cpp) bound
/// that.
/// `specs` are the options c.options holds the values of, in the same order.
int maxSteps(const RandomCase& c, std::span<const OptionSpec> specs) {
  constexpr double kBallSteps = 20'000.0;
  constexpr double kSubstepSteps = 1'600.0;
  constexpr double kThreadRepeats = 16.0;
  double repeats = 1.0;
  for (std::size_t i = 0; i < specs.size(); ++i) {
    const double value = c.options[i].second;
    if (specs[i].role == OptionRole::Substeps) repeats *= value;
    if (specs[i].role == OptionRole::Threads) repeats *= 1.0 + kThreadRepeats * (value - 1.0);
  }
  const double balls = static_cast<double>(std::max<std::size_t>(c.scene.balls.size(), 1));
  return static_cast<int>(
      std::clamp(std::min(kBallSteps / balls, kSubstepSteps / repeats), 1.0, 400.0));
}

void drawEvents(RandomCase& c, Draw& draw) {
  const std::size_t balls = c.scene.balls.size();
  const Box box = c.scene.box;
  for (int i = draw.integer(0, 2); i > 0; --i) {
    ToolUse tool;
    tool.start = draw.integer(0, c.steps - 1);
    tool.duration = draw.integer(1, c.steps - tool.start);
    tool.mode = static_cast<MouseMode>(draw.integer(0, 3));
    tool.scope = draw.chance(0.5) ? Scope::All : Scope::Nearest;
    tool.point = {draw.uniform(0.0, box.width), draw.uniform(0.0, box.height)};
    tool.strength = draw.logUniform(0.1, 1000.0);
    c.tools.push_back(tool);
  }
  for (int i = draw.integer(0, 2); i > 0; --i) {
    WorldChange change{draw.integer(0, c.steps - 1), drawWorld(draw)};
    if (c.scene.world.walls.allOn()) change.world.walls = {};
    c.worldChanges.push_back(change);
  }
  for (int i = balls == 0 ? 0 : draw.integer(0, 3); i > 0; --i) {
    BallEdit edit;
    edit.step = draw.integer(0, c.steps - 1);
    edit.index = static_cast<std::size_t>(draw.integer(0, static_cast<int>(balls) - 1));
    const BallDef& ball = c.scene.balls[edit.index];
    edit.velocity = draw.logUniform(1e-3, 10.0) * (1.0 + length(ball.velocity)) * draw.direction();
    edit.radiusScale = draw.uniform(0.1, 1.0);
    edit.mass = ball.mass * draw.logUniform(1e-2, 1e2);
    c.edits.push_back(edit);
  }
  std::sort(c.worldChanges.begin(), c.worldChanges.end(),
            [](const WorldChange& a, const WorldChange& b) { return a.step < b.step; });
}

const char* modeName(MouseMode mode) {
  switch (mode) {
    case MouseMode::Attract:
      return "attract";
    case MouseMode::Repel:
      return "repel";
    case MouseMode::Grab:
      return "grab";
    case MouseMode::Slingshot:
      return "slingshot";
  }
  return "?";
}

void describeWorld(std::ostream& out, const WorldSettings& world) {
  out << "gravity (" << world.gravity.x << ", " << world.gravity.y << ") m/s², drag "
      << world.airResistance << " 1/s, ball collisions " << (world.ballCollisions ? "on" : "off")
      << ", walls L" << world.walls.left << " R" << world.walls.right << " B" << world.walls.bottom
      << " T" << world.walls.top;
}

}  // namespace

bool RandomCase::isolated() const {
  return tools.empty() && edits.empty() && worldChanges.empty() && scene.world.airResistance == 0.0;
}

bool RandomCase::closed() const {
  return scene.world.walls.allOn() &&
         std::all_of(worldChanges.begin(), worldChanges.end(),
                     [](const WorldChange& change) { return change.world.walls.allOn(); });
}

RandomCase drawCase(std::uint64_t seed, std::span<const OptionSpec> options) {
  Draw draw(seed);
  RandomCase c;
  c.seed = seed;
  c.scene.name = "random case " + std::to_string(seed);
  c.scene.box.width = draw.logUniform(0.5, 200.0);
  c.scene.box.height = c.scene.box.width * draw.logUniform(0.2, 5.0);
  c.scene.world = drawWorld(draw);
  drawBalls(c.scene, draw);
  c.options = drawOptions(draw, options);
  c.dt = draw.logUniform(1e-4, 0.05);
  c.steps = draw.logInteger(1, maxSteps(c, options));
  if (draw.chance(0.5)) drawEvents(c, draw);
  return c;
}

std::string describe(const RandomCase& c) {
  std::ostringstream out;
  out.precision(17);
  out << "case seed " << c.seed << ": " << c.scene.balls.size() << " balls in a "
      << c.scene.box.width << " × " << c.scene.box.height << " m box, " << c.steps << " steps of "
      << c.dt << " s\n  world: ";
  describeWorld(out, c.scene.world);
  out << "\n  options:";
  for (const auto& [name, value] : c.options)
    out << " " << name << "=" << value;
  for (const ToolUse& tool : c.tools) {
    out << "\n  tool " << modeName(tool.mode)
        << (tool.scope == Scope::All ? " (all)" : " (nearest)") << " at (" << tool.point.x << ", "
        << tool.point.y << ") strength " << tool.strength << " from step " << tool.start << " for "
        << tool.duration;
  }
  for (const WorldChange& change : c.worldChanges) {
    out << "\n  at step " << change.step << " world: ";
    describeWorld(out, change.world);
  }
  for (const BallEdit& edit : c.edits) {
    out << "\n  at step " << edit.step << " setBall " << edit.index << ": velocity ("
        << edit.velocity.x << ", " << edit.velocity.y << "), radius ×" << edit.radiusScale
        << ", mass " << edit.mass;
  }
  return out.str();
}

}  // namespace fooball::robustness
