#pragma once

#include <memory>

#include "fooball/backend.h"

namespace fooball {

std::unique_ptr<Backend> makeChipmunkBackend();

}  // namespace fooball
