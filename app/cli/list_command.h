#pragma once

#include <ostream>

namespace fooball::cli {

/// `fooball-cli list`: the backends with their options (name, default, range, description),
/// then the presets, as aligned text.
void printList(std::ostream& out);

}  // namespace fooball::cli
