#pragma once

#include "fooball/scene.h"
#include "json_place.h"

namespace fooball {

/// The rules of validateScene and validateBall, throwing SceneError("PLACE: REASON") for
/// callers that put the source in front themselves.
void checkScene(const Scene& scene);
void checkBall(const BallDef& ball, const Box& box, const Walls& walls, const Place& place);

}  // namespace fooball
