#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "fooball/scene.h"
#include "fooball/scene_error.h"

namespace fooball {

/// Why one ball may not be where it is (a scene file) or where an edit would put it (the app's
/// inspector, an undo): the kind and what a message needs, so each front end words it its own
/// way. Scene files say `balls[3].radius: must be > 0 (got -1)` (validateScene); the app says
/// "The radius must be more than 0." (plainWords).
struct BallProblem {
  enum class Kind {
    NotFinite,    ///< `quantity` (component `component`) is NaN or infinite
    NotPositive,  ///< `quantity` (radius or mass) is <= 0
    TooLarge,     ///< the radius is beyond kMaxBoxSide
    NotAColour,   ///< the colour has bits above 0xffffff
    CrossesWall,  ///< the ball reaches through `wall` by more than kContactSlop of its radius
    Overlaps,     ///< the ball overlaps ball `otherBall` by more than kContactSlop
  };
  Kind kind = Kind::NotFinite;
  /// The scene format's key: "position", "velocity", "radius", "mass" or "color".
  std::string_view quantity;
  int component = -1;  ///< 0 (x) or 1 (y) of a position or velocity; -1 for a number
  /// The value refused (NotFinite, NotPositive, TooLarge, NotAColour: the colour as a number);
  /// CrossesWall: m beyond the wall; Overlaps: the depth as a fraction of the smaller radius.
  double value = 0.0;
  std::string_view wall;      ///< CrossesWall: "left", "right", "bottom" or "top"
  std::size_t otherBall = 0;  ///< Overlaps: the other ball's scene index
};

/// The problem in words for someone editing the ball, one sentence: "The ball would overlap
/// ball 19 (by 12% of the smaller radius).", "The ball would stick out of the box through the
/// left wall.", "The radius must be more than 0."
std::string plainWords(const BallProblem& problem);

/// The first rule of the scene format `ball` breaks wherever it is: finite position and
/// velocity, radius in (0, kMaxBoxSide], mass > 0, a 0xRRGGBB colour (checked in this order).
std::optional<BallProblem> findValueProblem(const BallDef& ball);
/// findValueProblem, then the inside-the-box rule for each wall that is on.
std::optional<BallProblem> findBallProblem(const BallDef& ball, const Box& box, const Walls& walls);
/// The deepest overlap beyond kContactSlop of `ball` with the balls at `positions` and `radii`
/// (scene order), leaving out `skip` (the ball's own index when it replaces one). O(N): one ball
/// against the others, as an edit needs.
std::optional<BallProblem> findOverlapProblem(const BallDef& ball, std::span<const Vec2> positions,
                                              std::span<const double> radii,
                                              std::optional<std::size_t> skip);

/// A ball refused by an edit (Simulation::setBall, RunGroup::setBall and restoring a ball):
/// what() is the technical line, "balls[0]: would overlap balls[19]"; problem() is for
/// plainWords.
class BallError : public SceneError {
 public:
  BallError(const std::string& what, const BallProblem& problem)
      : SceneError(what), problem_(problem) {}
  const BallProblem& problem() const { return problem_; }

 private:
  BallProblem problem_;
};

}  // namespace fooball
