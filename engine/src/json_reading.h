#pragma once

#include <array>
#include <cstdint>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "fooball/vec2.h"
#include "json_place.h"

namespace fooball {

/// Typed access to parsed scene JSON. Each function checks the JSON type and shape and throws
/// SceneError("PLACE: REASON") naming what was expected and what was found; value ranges
/// (radius > 0, …) are the validator's job, so in-memory scenes get the same checks.

/// "an object", "an array of 3 elements", "the number 2.5", "the string \"16\"", "true", "null".
std::string describeJson(const nlohmann::json& value);

void requireObject(const nlohmann::json& value, const Place& place);

/// Fails on the first key of `object` that is not in `known`, listing the known keys.
void checkKnownKeys(const nlohmann::json& object, const Place& place,
                    std::initializer_list<std::string_view> known);

/// The member named `name` of an object, or nullptr when it has none.
const nlohmann::json* findMember(const nlohmann::json& object, std::string_view name);
const nlohmann::json& requireMember(const nlohmann::json& object, const Place& place,
                                    std::string_view name);

double readNumber(const nlohmann::json& value, const Place& place);
bool readBool(const nlohmann::json& value, const Place& place);
std::string readString(const nlohmann::json& value, const Place& place);
/// A JSON integer ≥ 0 that fits in 64 bits (2.0 is not an integer here: counts and seeds are
/// written as integers).
std::uint64_t readUnsigned(const nlohmann::json& value, const Place& place);

/// An array of exactly two numbers; `shape` names them in the message, e.g. "[x, y]".
std::array<double, 2> readNumberPair(const nlohmann::json& value, const Place& place,
                                     std::string_view shape);
Vec2 readVec2(const nlohmann::json& value, const Place& place);

/// "#rrggbb" (hex digits in either case) as 0xRRGGBB.
std::uint32_t readColor(const nlohmann::json& value, const Place& place);

}  // namespace fooball
