// Steps one configuration of box2d_benchmark's standard gas for a fixed number of 1/60 s steps,
// on the Box2D backend or on the raw Box2D scene, so that callgrind can count the instructions of
// exactly those steps. Instruction counts repeat to a few in a billion whatever else the machine
// runs, where wall-clock ratios on a shared VM move by ±25% (docs/performance.md):
//
//   valgrind --tool=callgrind --toggle-collect='*timedSteps*' box2d_steps backend 5000 20 4 60
//
// prints, in its "Collected :" line, the instructions of 60 steps after one untimed step, as
// Box2dGasStep/5000/20/4 times them; `raw` instead of `backend` does the same for
// RawBox2dGasStep, and `bare` for the backend's own bodies stepped without the adapter
// (bare_box2d_world.h), whose difference from `backend` is the adapter's overhead.

#include <charconv>
#include <cstdio>
#include <string_view>
#include <system_error>

#include "bare_box2d_world.h"
#include "box2d/box2d_backend.h"
#include "fooball/standard_scenes.h"
#include "raw_box2d_world.h"

namespace {

using fooball::Backend;
using fooball::benchmarks::BareBox2dWorld;
using fooball::benchmarks::RawBox2dWorld;

constexpr double kDt = 1.0 / 60.0;  // s, as box2d_benchmark

/// The steps callgrind counts (--toggle-collect): kept out of line so they have a symbol.
[[gnu::noinline]] void timedSteps(Backend& backend, int steps) {
  for (int step = 0; step < steps; ++step)
    backend.step(kDt, {});
}

/// A world stepped `substeps` Box2D steps per step: RawBox2dWorld or BareBox2dWorld.
template <class World>
[[gnu::noinline]] void timedSteps(World& world, int substeps, int steps) {
  for (int step = 0; step < steps; ++step)
    world.step(kDt, substeps);
}

template <class World>
void stepWorld(const fooball::Scene& scene, int substeps, int steps) {
  World world(scene);
  world.step(kDt, substeps);
  timedSteps(world, substeps, steps);
}

bool parse(std::string_view text, int& value) {
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size() && value > 0;
}

}  // namespace

int main(int argc, char** argv) {
  int balls = 0;
  int phiPercent = 0;
  int substeps = 0;
  int steps = 0;
  const std::string_view world = argc == 6 ? argv[1] : "";
  if ((world != "backend" && world != "raw" && world != "bare") || !parse(argv[2], balls) ||
      !parse(argv[3], phiPercent) || !parse(argv[4], substeps) || !parse(argv[5], steps)) {
    std::fputs("usage: box2d_steps backend|raw|bare BALLS PHI_PERCENT SUBSTEPS STEPS\n", stderr);
    return 2;
  }
  const fooball::Scene scene =
      fooball::standardGas(static_cast<std::size_t>(balls), phiPercent / 100.0);
  if (world == "backend") {
    auto backend = fooball::makeBox2dBackend();
    backend->setOption("substeps", substeps);
    backend->load(scene);
    backend->step(kDt, {});
    timedSteps(*backend, steps);
  } else if (world == "raw") {
    stepWorld<RawBox2dWorld>(scene, substeps, steps);
  } else {
    stepWorld<BareBox2dWorld>(scene, substeps, steps);
  }
  return 0;
}
