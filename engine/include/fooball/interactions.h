#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "fooball/vec2.h"

namespace fooball {

/// What the cursor does while a button is held.
enum class MouseMode { Attract, Repel, Grab, Slingshot };

/// Which balls the cursor tool acts on. Permanent attractors always act on all balls.
enum class Scope { All, Nearest, Selected };

/// The balls as the interactions see them (scene order).
struct BallsView {
  std::span<const Vec2> positions;   ///< m
  std::span<const Vec2> velocities;  ///< m/s
  std::span<const double> radii;     ///< m
  std::span<const double> masses;    ///< kg
};

/// Mouse tools and permanent attractors, turned into per-ball forces. Backend-agnostic: the
/// driver hands the forces to any backend's step(). All forces are mass-proportional
/// (F = m·a), so a tool moves big and small balls alike.
class Interactions {
 public:
  /// 1/s², what strength starts at (and Reset sliders goes back to).
  static constexpr double kDefaultStrength = 10.0;

  MouseMode mode = MouseMode::Attract;
  Scope scope = Scope::All;
  /// 1/s²: attract/repel acceleration per metre of distance to the cursor (a spring of
  /// ω = √strength); the slingshot launches at 0.2·strength m/s per metre of pull.
  double strength = kDefaultStrength;
  std::optional<std::size_t> selected;  ///< the ball Scope::Selected acts on

  /// A press at `point` (m). Grab and slingshot take the target ball (nearestBall: the one
  /// under the point or else the nearest, or the selected one) here.
  void press(Vec2 point, const BallsView& balls);
  void move(Vec2 point) { cursor_ = point; }
  /// Ends the press; the slingshot fires on the next forces() call.
  void release(Vec2 point);
  bool pressed() const { return pressed_; }
  Vec2 cursor() const { return cursor_; }

  void addAttractor(Vec2 point) { attractors_.push_back(point); }
  void clearAttractors() { attractors_.clear(); }
  std::span<const Vec2> attractors() const { return attractors_; }

  /// The ball the held tool acts on, if it acts on one ball (for drawing tethers).
  std::optional<std::size_t> target() const { return target_; }

  /// True when forces() would give a non-zero force to some ball.
  bool active() const;

  /// Writes the force (N) on every ball for a step of `dt` seconds into `forces`
  /// (balls.positions.size() elements; overwritten).
  void forces(const BallsView& balls, double dt, std::span<Vec2> forces);

  /// Forgets the target balls, e.g. after balls were removed.
  void forgetBalls();

 private:
  std::optional<std::size_t> pickTarget(Vec2 point, const BallsView& balls) const;

  bool pressed_ = false;
  Vec2 cursor_;
  Vec2 pressPoint_;
  std::optional<std::size_t> target_;
  std::optional<Vec2> pendingLaunch_;  ///< Δv (m/s) the slingshot gives on the next step
  std::vector<Vec2> attractors_;
};

/// The ball a press at `point` takes, if there are balls: the one under it, or else the one whose
/// edge is nearest (not its centre: beside a big ball, a small ball's centre may be nearer
/// than the big ball's edge the user pressed). Among overlapping balls under it, the one it is
/// deepest in.
std::optional<std::size_t> nearestBall(Vec2 point, std::span<const Vec2> positions,
                                       std::span<const double> radii);

}  // namespace fooball
