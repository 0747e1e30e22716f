#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace fooball {

/// Where a value sits in a scene, as a JSON path: `box.width`, `balls[3].position[1]`.
///
/// A Place is a chain of links on the stack, so reading a million balls builds no strings; the
/// text is made only for an error message. A child refers to its parent, so the parent must
/// outlive it: name each level (`const Place ball = balls.index(i);`), never a child of a
/// temporary.
class Place {
 public:
  /// The top level of the document: its children print as bare keys (`box`, `balls[3]`).
  Place() = default;
  /// A root with a name of its own, e.g. "balls[3]" handed in by a caller.
  explicit Place(std::string_view root) : name_(root) {}

  Place key(std::string_view name) const { return Place(this, name, false, 0); }
  Place index(std::size_t position) const { return Place(this, {}, true, position); }

  std::string text() const;

 private:
  Place(const Place* parent, std::string_view name, bool isIndex, std::size_t position)
      : parent_(parent), name_(name), isIndex_(isIndex), index_(position) {}

  const Place* parent_ = nullptr;
  std::string_view name_;
  bool isIndex_ = false;
  std::size_t index_ = 0;
};

/// Throws SceneError("PLACE: REASON"), or just REASON at the top level; the caller that knows
/// the file or preset adds it in front.
[[noreturn]] void failAt(const Place& place, std::string_view reason);

}  // namespace fooball
