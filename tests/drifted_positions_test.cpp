// driftedPositions: where the app draws the balls between steps, τ of simulated time after the
// last one. In free flight that is where a step of τ would put them; a wall that is on stops the
// drawn ball; at τ = 0 it is the stepped state to the last bit.

#include "fooball/drifted_positions.h"

#include <gtest/gtest.h>

#include <vector>

#include "fooball/simulation.h"
#include "registry.h"
#include "test_scenes.h"

namespace fooball {
namespace {

using testing::ball;
using testing::emptyBox;

Simulation simulationOf(const Scene& scene) {
  return Simulation(scene, createBackend("elastic"));
}

TEST(DriftedPositions, AreWhereAStepOfTheSameTimeTakesABallInFreeFlight) {
  Scene scene = emptyBox();
  scene.world.gravity = {0.0, -9.81};
  scene.balls = {ball({4.0, 5.0}, {3.0, 2.0}, 0.3), ball({10.0, 6.0}, {-1.5, -0.5}, 0.2)};
  const Simulation run = simulationOf(scene);
  const double tau = 0.01;  // s: less than a step, as the frame loop has it
  std::vector<Vec2> drawn;
  driftedPositions(run, tau, drawn);

  Simulation stepped = simulationOf(scene);  // elastic flies in closed form: exact to rounding
  stepped.setDt(tau);
  stepped.step();
  ASSERT_EQ(drawn.size(), 2u);
  for (std::size_t i = 0; i < drawn.size(); ++i) {
    EXPECT_NEAR(drawn[i].x, stepped.positions()[i].x, 1e-12) << i;
    EXPECT_NEAR(drawn[i].y, stepped.positions()[i].y, 1e-12) << i;
  }
  EXPECT_NE(drawn[0].x, run.positions()[0].x) << "the drawn ball moved ahead";
}

TEST(DriftedPositions, AreTheSteppedStateWhenNothingIsPending) {
  Scene scene = emptyBox();
  scene.world.gravity = {0.0, -9.81};
  scene.balls = {ball({4.0, 5.0}, {3.0, 2.0}, 0.3)};
  const Simulation run = simulationOf(scene);
  std::vector<Vec2> drawn;
  driftedPositions(run, 0.0, drawn);
  ASSERT_EQ(drawn.size(), 1u);
  EXPECT_EQ(drawn[0], run.positions()[0]);
}

TEST(DriftedPositions, StopAtAWallThatIsOnAndPassOneThatIsOff) {
  Scene scene = emptyBox(16.0, 9.0);
  // 0.05 m from touching the right wall, 0.2 m from touching the top, moving 6 m/s into each.
  scene.balls = {ball({15.45, 4.5}, {6.0, 0.0}, 0.5), ball({4.0, 8.3}, {0.0, 6.0}, 0.5)};
  const double tau = 1.0 / 60.0;  // s: 0.1 m of travel
  std::vector<Vec2> drawn;
  driftedPositions(simulationOf(scene), tau, drawn);
  EXPECT_DOUBLE_EQ(drawn[0].x, 15.5) << "stopped touching the right wall";
  EXPECT_DOUBLE_EQ(drawn[1].y, 8.4) << "0.1 m closer to the top, still short of it";

  scene.world.walls.right = false;
  driftedPositions(simulationOf(scene), tau, drawn);
  EXPECT_DOUBLE_EQ(drawn[0].x, 15.55) << "no wall: on through where it was";
}

TEST(DriftedPositions, LeaveABallPressedIntoAWallWhereTheStepPutIt) {
  // A saved state may have a ball pressed into a wall (within the contact slop); the drawn ball
  // must not jump out of it to the contact position, nor sink further.
  Scene scene = emptyBox();
  scene.balls = {ball({0.49, 4.5}, {-1.0, 0.0}, 0.5)};
  std::vector<Vec2> drawn;
  driftedPositions(simulationOf(scene), 0.01, drawn);
  EXPECT_EQ(drawn[0].x, 0.49);
}

}  // namespace
}  // namespace fooball
