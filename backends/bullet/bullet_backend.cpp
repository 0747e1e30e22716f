#include "bullet/bullet_backend.h"

#include <LinearMath/btScalar.h>

#include "bullet_adapter.h"

namespace fooball {

static_assert(BT_BULLET_VERSION == 324,
              "kBulletDescription names Bullet 3.24: state the version btGetVersion() reports");

std::unique_ptr<Backend> makeBulletBackend() {
  return std::make_unique<bullet_detail::BulletAdapter>();
}

}  // namespace fooball
