#pragma once

#include <string_view>

#include "fooball/scene.h"
#include "json_place.h"

namespace fooball {

/// The rules of validateScene and validateBall, throwing SceneError("PLACE: REASON") for
/// callers that put the source in front themselves.
void checkScene(const Scene& scene);
void checkBall(const BallDef& ball, const Box& box, const Walls& walls, const Place& place);

/// A backend or option name in saved_from: 1 to kMaxSpecNameBytes letters, digits, '_' or '-',
/// so that it reads back as a run spec (NAME:KEY=VALUE) and shows as one printable line.
/// `what` names it in the message, e.g. "an option name".
inline constexpr std::size_t kMaxSpecNameBytes = 64;
void checkSpecName(std::string_view name, const Place& place, std::string_view what);

}  // namespace fooball
