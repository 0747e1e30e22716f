// Scale: the same 40-ball gas with every length and speed multiplied by s, so at every s
// it is the same motion in units of r and of the step. A solver in double with relative
// tolerances does not care; Box2D does: its linear slop (0.005 m) and AABB margin (0.1 m) are
// absolute lengths, its positions are float (7 digits), and b2_maxTranslation caps a body at
// 2 m per Box2D step.

#include "fooball/random_balls.h"
#include "fooball/scene.h"
#include "sweep_run.h"
#include "sweeps.h"

namespace fooball::failure_map {

namespace {

/// The 16 × 9 m gas of 40 balls (radius 0.2–0.4 m, 1–3 m/s, about 100 ball–ball hits in 2 s)
/// with every length and speed multiplied by `scale`; density 1 kg/m² at every scale.
Scene scaledGas(double scale) {
  Scene scene;
  scene.name = "scale";
  RandomBalls spec;
  spec.count = 40;
  spec.minRadius = 0.2;
  spec.maxRadius = 0.4;
  spec.minSpeed = 1.0;
  spec.maxSpeed = 3.0;
  spec.seed = 11;
  addRandomBalls(scene, spec);
  scene.box = {16.0 * scale, 9.0 * scale};
  for (BallDef& ball : scene.balls) {
    ball.position *= scale;
    ball.velocity *= scale;
    ball.radius *= scale;
    ball.mass = diskMass(ball.radius);
  }
  return scene;
}

}  // namespace

std::vector<SweepPoint> scaleSweep(std::string_view backend, bool quick) {
  std::vector<SweepPoint> points;
  for (const double scale : logGrid(1e-4, 1e4, quick ? 9 : 17)) {
    const Scene scene = scaledGas(scale);
    const RunRecord run = runScene(scene, backend, quick ? 1.0 : 2.0);
    points.push_back(measuredPoint(scene, "40 balls", scale, run.energyError, run.maxOverlap));
  }
  return points;
}

}  // namespace fooball::failure_map
