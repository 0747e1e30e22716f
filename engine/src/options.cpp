#include "fooball/options.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>

#include "fooball/number_text.h"

namespace fooball {

OptionSet::OptionSet(std::vector<OptionSpec> specs) : specs_(std::move(specs)) {
  values_.reserve(specs_.size());
  for (const OptionSpec& spec : specs_)
    values_.push_back(spec.defaultValue);
}

std::size_t OptionSet::indexOf(std::string_view name) const {
  for (std::size_t i = 0; i < specs_.size(); ++i) {
    if (specs_[i].name == name) return i;
  }
  std::string known;
  for (const OptionSpec& spec : specs_)
    known += (known.empty() ? "" : ", ") + spec.name;
  throw std::invalid_argument("unknown option '" + std::string(name) +
                              "' (options: " + (known.empty() ? "none" : known) + ")");
}

bool OptionSet::has(std::string_view name) const {
  return std::any_of(specs_.begin(), specs_.end(),
                     [&](const OptionSpec& spec) { return spec.name == name; });
}

const OptionSpec* OptionSet::withRole(OptionRole role) const {
  const auto found = std::find_if(specs_.begin(), specs_.end(),
                                  [&](const OptionSpec& spec) { return spec.role == role; });
  return found == specs_.end() ? nullptr : &*found;
}

double OptionSet::value(std::string_view name) const {
  return values_[indexOf(name)];
}

void OptionSet::set(std::string_view name, double value) {
  const std::size_t index = indexOf(name);
  const OptionSpec& spec = specs_[index];
  const std::string where = "option '" + spec.name + "': ";
  if (!std::isfinite(value)) throw std::invalid_argument(where + "must be a finite number");
  if (spec.integer && value != std::floor(value)) {
    throw std::invalid_argument(where + "must be a whole number (got " + exactNumberText(value) +
                                ")");
  }
  if (value < spec.min || value > spec.max) {
    throw std::invalid_argument(where + "must be in [" + exactNumberText(spec.min) + ", " +
                                exactNumberText(spec.max) + "] (got " + exactNumberText(value) +
                                ")");
  }
  values_[index] = value;
}

void OptionSet::setFromText(std::string_view assignment) {
  const std::size_t equals = assignment.find('=');
  if (equals == std::string_view::npos || equals == 0) {
    throw std::invalid_argument("option '" + std::string(assignment) + "': expected KEY=VALUE");
  }
  const std::string_view name = assignment.substr(0, equals);
  const std::string_view text = assignment.substr(equals + 1);
  const OptionSpec& spec = specs_[indexOf(name)];
  std::string known;  // a named choice by its name; its index, as a number, also sets it
  for (std::size_t i = 0; i < spec.choices.size(); ++i) {
    if (spec.choices[i] == text) return set(name, static_cast<double>(i));
    known += (known.empty() ? "" : ", ") + spec.choices[i];
  }
  const bool isSwitch = spec.integer && spec.min == 0.0 && spec.max == 1.0;
  if (isSwitch && (text == "true" || text == "on")) return set(name, 1.0);
  if (isSwitch && (text == "false" || text == "off")) return set(name, 0.0);
  double value = 0.0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  if (result.ec != std::errc() || result.ptr != text.data() + text.size()) {
    throw std::invalid_argument("option '" + spec.name + "': '" + std::string(text) +
                                (known.empty() ? "' is not a number" : "' is not one of " + known));
  }
  set(name, value);
}

}  // namespace fooball
