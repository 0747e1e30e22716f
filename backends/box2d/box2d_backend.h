#pragma once

#include <memory>

#include "fooball/backend.h"

namespace fooball {

std::unique_ptr<Backend> makeBox2dBackend();

}  // namespace fooball
