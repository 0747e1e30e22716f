#pragma once

#include <stdexcept>
#include <string>

namespace fooball {

/// An invalid scene or scene file. what() is one line naming the place and the reason,
/// e.g. "scene.json: balls[3].radius: must be > 0 (got -1)".
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace fooball
