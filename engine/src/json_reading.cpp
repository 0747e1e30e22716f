#include "json_reading.h"

#include <algorithm>

#include "message_text.h"

namespace fooball {
namespace {

using Json = nlohmann::json;

[[noreturn]] void failType(const Json& value, const Place& place, std::string_view expected) {
  failAt(place, "must be " + std::string(expected) + " (got " + describeJson(value) + ")");
}

int hexDigitValue(char digit) {
  if (digit >= '0' && digit <= '9') return digit - '0';
  if (digit >= 'a' && digit <= 'f') return digit - 'a' + 10;
  if (digit >= 'A' && digit <= 'F') return digit - 'A' + 10;
  return -1;
}

}  // namespace

std::string describeJson(const Json& value) {
  switch (value.type()) {
    case Json::value_t::null:
      return "null";
    case Json::value_t::boolean:
      return value.get<bool>() ? "true" : "false";
    case Json::value_t::number_integer:
      return "the number " + std::to_string(value.get<std::int64_t>());
    case Json::value_t::number_unsigned:
      return "the number " + std::to_string(value.get<std::uint64_t>());
    case Json::value_t::number_float: {
      // As JSON would write it: 1.0 stays "1.0", or "must be an integer (got 1)" would puzzle.
      std::string text = exactNumberText(value.get<double>());
      if (text.find_first_of(".e") == std::string::npos) text += ".0";
      return "the number " + text;
    }
    case Json::value_t::string:
      return "the string " + quotedText(value.get_ref<const std::string&>());
    case Json::value_t::array:
      return value.size() == 1 ? "an array of 1 element"
                               : "an array of " + std::to_string(value.size()) + " elements";
    case Json::value_t::object:
      return "an object";
    case Json::value_t::binary:
    case Json::value_t::discarded:
      break;
  }
  return value.type_name();
}

void requireObject(const Json& value, const Place& place) {
  if (!value.is_object()) failType(value, place, "an object");
}

void checkKnownKeys(const Json& object, const Place& place,
                    std::initializer_list<std::string_view> known) {
  for (const auto& [key, value] : object.items()) {
    if (std::find(known.begin(), known.end(), key) != known.end()) continue;
    std::string list;
    for (const std::string_view name : known) {
      if (!list.empty()) list += ", ";
      list += name;
    }
    failAt(place, "unknown key " + quotedText(key) + " (known keys: " + list + ")");
  }
}

const Json* findMember(const Json& object, std::string_view name) {
  const auto member = object.find(name);
  return member == object.end() ? nullptr : &*member;
}

const Json& requireMember(const Json& object, const Place& place, std::string_view name) {
  const Json* member = findMember(object, name);
  if (member == nullptr) failAt(place, "missing required key \"" + std::string(name) + "\"");
  return *member;
}

double readNumber(const Json& value, const Place& place) {
  if (!value.is_number()) failType(value, place, "a number");
  return value.get<double>();
}

bool readBool(const Json& value, const Place& place) {
  if (!value.is_boolean()) failType(value, place, "true or false");
  return value.get<bool>();
}

std::string readString(const Json& value, const Place& place) {
  if (!value.is_string()) failType(value, place, "a string");
  return value.get<std::string>();
}

std::uint64_t readUnsigned(const Json& value, const Place& place) {
  if (value.is_number_unsigned()) return value.get<std::uint64_t>();
  if (value.is_number_integer()) {
    failAt(place, "must be >= 0 (got " + std::to_string(value.get<std::int64_t>()) + ")");
  }
  failType(value, place, "a whole number");
}

std::array<double, 2> readNumberPair(const Json& value, const Place& place,
                                     std::string_view shape) {
  if (!value.is_array() || value.size() != 2) failType(value, place, shape);
  return {readNumber(value[0], place.index(0)), readNumber(value[1], place.index(1))};
}

Vec2 readVec2(const Json& value, const Place& place) {
  const auto [x, y] = readNumberPair(value, place, "[x, y]");
  return {x, y};
}

std::uint32_t readColor(const Json& value, const Place& place) {
  constexpr std::string_view kShape = "a colour \"#rrggbb\"";
  if (!value.is_string()) failType(value, place, kShape);
  const std::string& text = value.get_ref<const std::string&>();
  if (text.size() != 7 || text[0] != '#') failType(value, place, kShape);
  std::uint32_t color = 0;
  for (std::size_t i = 1; i < text.size(); ++i) {
    const int digit = hexDigitValue(text[i]);
    if (digit < 0) failType(value, place, kShape);
    color = color << 4 | static_cast<std::uint32_t>(digit);
  }
  return color;
}

}  // namespace fooball
