#include "fooball/run_spec.h"

#include <stdexcept>

#include "fooball/number_text.h"

namespace fooball {

namespace {

[[noreturn]] void badSpec(std::string_view text, const std::string& reason) {
  throw std::invalid_argument("run spec '" + std::string(text) + "': " + reason);
}

std::string_view keyOf(std::string_view assignment) {
  return assignment.substr(0, assignment.find('='));
}

}  // namespace

std::string RunSpec::text() const {
  std::string text = backend;
  for (std::size_t i = 0; i < assignments.size(); ++i) {
    text += i == 0 ? ':' : ',';
    text += assignments[i];
  }
  return text;
}

void RunSpec::set(std::string_view key, double value) {
  const std::string assignment = std::string(key) + "=" + exactNumberText(value);
  for (std::string& existing : assignments) {
    if (keyOf(existing) == key) {
      existing = assignment;
      return;
    }
  }
  assignments.push_back(assignment);
}

RunSpec parseRunSpec(std::string_view text) {
  RunSpec spec;
  const std::size_t colon = text.find(':');
  spec.backend = std::string(text.substr(0, colon));
  if (spec.backend.empty()) badSpec(text, "expected NAME[:KEY=VALUE[,KEY=VALUE]...]");
  if (colon == std::string_view::npos) return spec;
  std::string_view rest = text.substr(colon + 1);
  while (true) {
    const std::size_t comma = rest.find(',');
    const std::string_view assignment = rest.substr(0, comma);
    const std::size_t equals = assignment.find('=');
    if (equals == 0 || equals == std::string_view::npos || equals + 1 == assignment.size()) {
      badSpec(text, "'" + std::string(assignment) + "' is not KEY=VALUE");
    }
    for (const std::string& earlier : spec.assignments) {
      if (keyOf(earlier) == keyOf(assignment)) {
        badSpec(text, "option '" + std::string(keyOf(assignment)) + "' is set twice");
      }
    }
    spec.assignments.emplace_back(assignment);
    if (comma == std::string_view::npos) return spec;
    rest = rest.substr(comma + 1);
  }
}

}  // namespace fooball
