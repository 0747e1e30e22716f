#include "json_place.h"

#include "fooball/scene_error.h"

namespace fooball {

std::string Place::text() const {
  if (parent_ == nullptr) return std::string(name_);
  std::string path = parent_->text();
  if (isIndex_) {
    path += '[';
    path += std::to_string(index_);
    path += ']';
  } else {
    if (!path.empty()) path += '.';
    path += name_;
  }
  return path;
}

void failAt(const Place& place, std::string_view reason) {
  std::string message = place.text();
  if (!message.empty()) message += ": ";
  message += reason;
  throw SceneError(message);
}

}  // namespace fooball
