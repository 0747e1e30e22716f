#include "box2d/box2d_backend.h"

#include "box2d_adapter.h"

namespace fooball {

std::unique_ptr<Backend> makeBox2dBackend() {
  return std::make_unique<box2d_detail::Box2dAdapter>();
}

}  // namespace fooball
