// States saved from running simulations (DESIGN.md, "Scene files", saved_from): whatever a
// registered backend produces — a pile under gravity, a dense packing, Box2D's float positions
// pressed into a wall, balls fallen past a wall that is off — is written with its saved_from,
// opens again bit for bit, is written again byte for byte, and loads and steps on every
// registered backend. The backends come from registeredBackends() alone, so a new one is tested
// by its registry line.

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <string>
#include <vector>

#include "fooball/presets.h"
#include "fooball/scene_file.h"
#include "fooball/simulation.h"
#include "registry.h"
#include "test_scenes.h"

namespace fooball {
namespace {

/// A state to save: a preset, run on one backend for a while.
struct SavedCase {
  const char* label;
  const char* preset;
  double seconds = 0.0;  ///< simulated
  bool bottomWallOff = false;
};

/// Rain piles up under gravity (balls pressed into each other and the floor); dense starts
/// near jamming; rain with the floor off drops balls out of the box.
constexpr SavedCase kCases[] = {
    {"rain pile", "rain", 3.0},
    {"dense packing", "dense", 2.0},
    {"rain through the floor", "rain", 1.5, true},
};

std::uint64_t bitsOf(double value) {
  return std::bit_cast<std::uint64_t>(value);
}

/// Every ball's position, velocity, radius and mass, bit for bit (-0.0 is not 0.0).
void expectSameBalls(const Scene& expected, const Scene& actual) {
  ASSERT_EQ(expected.balls.size(), actual.balls.size());
  for (std::size_t i = 0; i < expected.balls.size(); ++i) {
    const BallDef& e = expected.balls[i];
    const BallDef& a = actual.balls[i];
    for (const auto& [want, got] :
         {std::pair{e.position.x, a.position.x}, std::pair{e.position.y, a.position.y},
          std::pair{e.velocity.x, a.velocity.x}, std::pair{e.velocity.y, a.velocity.y},
          std::pair{e.radius, a.radius}, std::pair{e.mass, a.mass}}) {
      ASSERT_EQ(bitsOf(want), bitsOf(got)) << "balls[" << i << "]: " << want << " vs " << got;
    }
    ASSERT_EQ(e.color, a.color) << "balls[" << i << "]";
  }
}

Scene caseScene(const SavedCase& savedCase) {
  Scene scene = loadPreset(savedCase.preset);
  if (savedCase.bottomWallOff) scene.world.walls.bottom = false;
  return scene;
}

/// `savedCase` run on `backend`, as File → Save and run --save write it.
Scene savedStateOf(const SavedCase& savedCase, std::string_view backend) {
  Simulation simulation(caseScene(savedCase), createBackend(backend));
  simulation.run(savedCase.seconds);
  return simulation.savedScene(backend);
}

TEST(SavedStatesOnEveryBackend, EveryBackendsStateOpensAgainBitForBitWithItsSavedFrom) {
  bool someStateBreaksTheHandWrittenRules = false;
  for (const BackendInfo& info : registeredBackends()) {
    for (const SavedCase& savedCase : kCases) {
      SCOPED_TRACE(std::string(info.name) + ", " + savedCase.label);
      const Scene saved = savedStateOf(savedCase, info.name);
      ASSERT_TRUE(saved.savedFrom.has_value());
      EXPECT_EQ(saved.savedFrom->backend, info.name);
      EXPECT_NEAR(saved.savedFrom->time, savedCase.seconds, 1e-9);
      const auto backend = info.create();
      EXPECT_EQ(saved.savedFrom->options.size(), backend->options().specs().size())
          << "every option is recorded";

      if (savedCase.bottomWallOff) {
        EXPECT_TRUE(std::any_of(saved.balls.begin(), saved.balls.end(), [](const BallDef& ball) {
          return ball.position.y < 0.0;
        })) << "some ball fell out of the box";
      }
      const std::string written = writeScene(saved);
      Scene reopened;
      ASSERT_NO_THROW(reopened = parseScene(written, "saved.json"));
      expectSameBalls(saved, reopened);
      ASSERT_TRUE(reopened.savedFrom.has_value());
      EXPECT_EQ(*reopened.savedFrom, *saved.savedFrom);
      EXPECT_EQ(reopened.world, saved.world);
      EXPECT_EQ(writeScene(reopened), written) << "write → read → write changed the bytes";
      if (!savedStateWarning(reopened, "saved.json").empty())
        someStateBreaksTheHandWrittenRules = true;
    }
  }
  // Without saved_from these states would be refused: the test covers what issue #13 saw.
  EXPECT_TRUE(someStateBreaksTheHandWrittenRules);
}

TEST(SavedStatesOnEveryBackend, EveryBackendsStateLoadsAndStepsOnEveryBackend) {
  for (const BackendInfo& from : registeredBackends()) {
    for (const SavedCase& savedCase : kCases) {
      const Scene reopened =
          parseScene(writeScene(savedStateOf(savedCase, from.name)), "saved.json");
      for (const BackendInfo& on : registeredBackends()) {
        SCOPED_TRACE(std::string(from.name) + ", " + savedCase.label + ", on " +
                     std::string(on.name));
        Simulation simulation(reopened, on.create());
        simulation.run(0.1);
        for (const Vec2 position : simulation.positions())
          ASSERT_TRUE(std::isfinite(position.x) && std::isfinite(position.y));
        // Stepped on, the state saves and opens again too.
        const Scene again = simulation.savedScene(on.name);
        EXPECT_NO_THROW(parseScene(writeScene(again), "again.json"));
      }
    }
  }
}

TEST(SavedStatesOnEveryBackend, HandWrittenCopiesOfTheSameStatesAreStillChecked) {
  // The same bytes without saved_from are a hand-written file: the overlap and inside-the-box
  // rules apply again, so some state of some backend is refused.
  bool someRefused = false;
  for (const BackendInfo& info : registeredBackends()) {
    for (const SavedCase& savedCase : kCases) {
      Scene state = savedStateOf(savedCase, info.name);
      state.savedFrom.reset();
      try {
        parseScene(writeScene(state), "hand.json");
      } catch (const SceneError& error) {
        EXPECT_NE(std::string(error.what()).find("hand.json: balls["), std::string::npos)
            << error.what();
        someRefused = true;
      }
    }
  }
  EXPECT_TRUE(someRefused);
}

}  // namespace
}  // namespace fooball
