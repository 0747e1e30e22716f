#include "fooball/standard_scenes.h"

#include <cmath>
#include <numbers>

#include "fooball/random_balls.h"

namespace fooball {

Scene standardGas(std::size_t count, double packingFraction, std::uint64_t seed) {
  RandomBalls spec;
  spec.count = count;
  spec.minRadius = 0.1;
  spec.maxRadius = 0.2;
  spec.minSpeed = 0.5;
  spec.maxSpeed = 3.0;
  spec.seed = seed;
  // E[r²] for r uniform on [a, b] is (a² + ab + b²)/3.
  const double a = spec.minRadius;
  const double b = spec.maxRadius;
  const double meanBallArea = std::numbers::pi * (a * a + a * b + b * b) / 3.0;
  const double boxArea = static_cast<double>(count) * meanBallArea / packingFraction;
  const double height = std::sqrt(boxArea * 9.0 / 16.0);

  Scene scene;
  scene.name = "standard gas";
  scene.box = {height * 16.0 / 9.0, height};
  addRandomBalls(scene, spec);
  return scene;
}

}  // namespace fooball
