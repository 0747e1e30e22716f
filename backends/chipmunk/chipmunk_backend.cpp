#include "chipmunk/chipmunk_backend.h"

#include "chipmunk_adapter.h"

namespace fooball {

std::unique_ptr<Backend> makeChipmunkBackend() {
  return std::make_unique<chipmunk_detail::ChipmunkAdapter>();
}

}  // namespace fooball
