#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "fooball/backend.h"

namespace fooball {

/// One run's method: a backend's registry name and the options it sets, written
/// `NAME[:KEY=VALUE[,KEY=VALUE]...]` (DESIGN.md, "Runs, run specs and run groups"), e.g.
/// `elastic:substeps=16`. The same backend may appear in several runs with different options.
struct RunSpec {
  std::string backend;                   ///< registry name, e.g. "box2d"
  std::vector<std::string> assignments;  ///< "KEY=VALUE", in the order given

  /// The spec as text, which is also the run's label: "box2d:substeps=8,velocity_iterations=20".
  std::string text() const;
  /// Sets KEY to `value` (shortest text that reads back the same double), replacing an earlier
  /// assignment of KEY.
  void set(std::string_view key, double value);
  friend bool operator==(const RunSpec&, const RunSpec&) = default;
};

/// Parses `NAME[:KEY=VALUE[,KEY=VALUE]...]`. Throws std::invalid_argument naming the spec and
/// what is wrong with its form; names and values are checked when the backend is made.
RunSpec parseRunSpec(std::string_view text);

/// Makes the backend a spec names with its options set; throws std::invalid_argument naming
/// the spec and the reason (unknown backend or option, value out of range). The engine knows
/// no backend by name: the backends' registry provides this (createBackend(const RunSpec&)).
using BackendFactory = std::unique_ptr<Backend> (*)(const RunSpec& spec);

}  // namespace fooball
