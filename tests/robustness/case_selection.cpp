#include "case_selection.h"

#include <charconv>
#include <optional>
#include <string_view>

namespace fooball::robustness {
namespace {

/// A whole number, all of `text` (no sign, no spaces), or nothing.
std::optional<std::uint64_t> wholeNumber(std::string_view text) {
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc{} || end != text.data() + text.size() || text.empty()) return {};
  return value;
}

bool inCi(const std::function<const char*(const char*)>& environment) {
  const char* ci = environment("CI");
  if (ci == nullptr) return false;
  const std::string_view value(ci);
  return !value.empty() && value != "0" && value != "false";
}

}  // namespace

CaseSelection selectCases(const std::function<const char*(const char*)>& environment) {
  CaseSelection selection;
  std::uint64_t count = 2000;
  if (const char* sanitized = environment("FOOBALL_SANITIZED");
      sanitized != nullptr && std::string_view(sanitized) == "1") {
    count = 500;
  }
  if (const char* seed = environment("FOOBALL_CASE_SEED")) {
    const std::optional<std::uint64_t> value = wholeNumber(seed);
    if (!value) {
      selection.error = "FOOBALL_CASE_SEED=" + std::string(seed) + ": not a case seed (a number)";
      return selection;
    }
    if (inCi(environment)) {
      selection.error = "FOOBALL_CASE_SEED=" + std::string(seed) +
                        " is set in CI: the random suite would run that one case instead of its " +
                        std::to_string(count) + "; unset it";
      return selection;
    }
    selection.seeds = {*value};
    selection.notice = "FOOBALL_CASE_SEED=" + std::string(seed) + ": ran case " +
                       std::to_string(*value) + " only, not the " + std::to_string(count) +
                       " default cases";
    return selection;
  }
  if (const char* soak = environment("FOOBALL_SOAK")) {
    const std::optional<std::uint64_t> value = wholeNumber(soak);
    if (!value || *value == 0) {
      selection.error = "FOOBALL_SOAK=" + std::string(soak) + ": not a case count (a number ≥ 1)";
      return selection;
    }
    count = *value;
  }
  selection.seeds.resize(count);
  for (std::uint64_t i = 0; i < count; ++i)
    selection.seeds[i] = i + 1;
  return selection;
}

}  // namespace fooball::robustness
