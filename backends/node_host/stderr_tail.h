#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace fooball::node_host {

/// The last bytes a child wrote to its stderr, kept in a ring of fixed size, so that an error can
/// quote how the child's own account ends without the parent holding all it ever said.
class StderrTail {
 public:
  static constexpr std::size_t kCapacity = 4096;  ///< bytes kept

  void append(std::string_view bytes);
  /// The kept bytes, oldest first, from the start of the first whole line when the ring has
  /// wrapped; trailing whitespace dropped.
  std::string text() const;

 private:
  char ring_[kCapacity] = {};
  std::size_t next_ = 0;  ///< where the next byte goes
  bool wrapped_ = false;
};

}  // namespace fooball::node_host
