// BallProblem: why a ball may not be where an edit puts it, in words for the app's user, from
// the same rules that word scene-file errors (scene_file_test.cpp pins those).

#include "fooball/ball_problem.h"

#include <gtest/gtest.h>

#include "fooball/simulation.h"
#include "registry.h"
#include "test_scenes.h"

namespace fooball {
namespace {

using testing::ball;
using testing::emptyBox;

BallProblem problemOf(const BallDef& ball) {
  const auto problem = findBallProblem(ball, Box{}, Walls{});
  EXPECT_TRUE(problem);
  return problem.value_or(BallProblem{});
}

TEST(BallProblem, ValuesAndWallsInPlainWords) {
  BallDef flat = ball({4.0, 4.5}, {}, 0.5);
  flat.radius = 0.0;
  EXPECT_EQ(plainWords(problemOf(flat)), "The radius must be more than 0.");
  BallDef light = ball({4.0, 4.5}, {}, 0.5);
  light.mass = -1.0;
  EXPECT_EQ(plainWords(problemOf(light)), "The mass must be more than 0.");
  BallDef lost = ball({4.0, 4.5}, {}, 0.5);
  lost.velocity.y = std::numeric_limits<double>::infinity();
  EXPECT_EQ(plainWords(problemOf(lost)), "The y velocity must be a finite number.");
  EXPECT_EQ(plainWords(problemOf(ball({0.3, 4.5}, {}, 0.5))),
            "The ball would stick out of the box through the left wall.");
  EXPECT_EQ(plainWords(problemOf(ball({8.0, 8.9}, {}, 0.5))),
            "The ball would stick out of the box through the top wall.");
  EXPECT_FALSE(findBallProblem(ball({0.5, 0.5}, {}, 0.5), Box{}, Walls{})) << "in the corner";
  EXPECT_FALSE(findBallProblem(ball({0.3, 4.5}, {}, 0.5), Box{}, Walls{false, true, true, true}))
      << "the left wall is off";
}

TEST(BallProblem, AnEditOntoAnotherBallNamesTheDeepestOverlapInPlainWords) {
  Scene scene = emptyBox();
  scene.balls = {ball({4.0, 4.5}, {}, 0.5), ball({8.0, 4.5}, {}, 0.5), ball({9.0, 4.5}, {}, 0.5)};
  Simulation simulation(scene, createBackend(parseRunSpec("elastic")));
  BallDef moved = scene.balls[0];
  moved.position = {8.7, 4.5};  // 0.3 m deep into ball 1, 0.7 m into ball 2
  try {
    simulation.setBall(0, moved);
    ADD_FAILURE() << "moved onto two balls";
  } catch (const BallError& error) {
    EXPECT_EQ(error.problem().kind, BallProblem::Kind::Overlaps);
    EXPECT_EQ(error.problem().otherBall, 2u);
    EXPECT_NEAR(error.problem().value, 0.7 / 0.5, 1e-12);
    EXPECT_EQ(plainWords(error.problem()),
              "The ball would overlap ball 2 (by 140% of the smaller radius).");
    EXPECT_STREQ(error.what(), "balls[0]: would overlap balls[2]") << "the technical line stays";
  }
}

}  // namespace
}  // namespace fooball
