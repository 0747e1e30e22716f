#pragma once

#include <cstddef>
#include <functional>
#include <nlohmann/json.hpp>
#include <string_view>

namespace fooball {

/// How deeply `[` and `{` may nest in a scene file. The format itself needs 4 levels; the limit
/// only has to stop hostile input (a megabyte of `[`) before it reaches the parser.
inline constexpr int kMaxJsonDepth = 64;

/// Receives one element of the streamed top-level array and its index.
using JsonElementSink = std::function<void(const nlohmann::json& element, std::size_t index)>;

/// Parses the text of a scene file into JSON, stricter than plain JSON:
/// - nesting deeper than kMaxJsonDepth is refused by a scan before parsing;
/// - a key repeated within one object is an error (plain JSON keeps the last one silently);
/// - numbers beyond the range of a double are errors naming their place.
/// Each element of the top-level array `streamedKey` ("balls") goes to `sink` as soon as it is
/// parsed and is then dropped, so a million balls are never held as JSON all at once; the
/// returned document keeps that array, empty.
/// Throws SceneError without the source, e.g. "invalid JSON at line 3, column 7: …".
nlohmann::json parseSceneJson(std::string_view text, std::string_view streamedKey,
                              const JsonElementSink& sink);

}  // namespace fooball
