#pragma once

#include <stdexcept>

namespace fooball::cli {

/// The process exit codes of DESIGN.md ("fooball-cli (headless)").
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;   ///< anything that is not the user's input
inline constexpr int kExitBadInput = 2;  ///< bad arguments or a bad scene

/// A command-line argument that cannot be used; what() is one line naming the argument and
/// the reason. Reported with kExitBadInput, like SceneError and std::invalid_argument.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace fooball::cli
