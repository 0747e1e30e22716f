#pragma once

#include <LinearMath/btVector3.h>

#include "fooball/vec2.h"

namespace fooball::bullet_detail {

/// The scene's double 2D vectors as Bullet's float 3D ones in the plane z = 0, and back.
inline btVector3 toBullet(Vec2 v) {
  return {static_cast<float>(v.x), static_cast<float>(v.y), 0.0f};
}

inline Vec2 fromBullet(const btVector3& v) {
  return {static_cast<double>(v.x()), static_cast<double>(v.y())};
}

}  // namespace fooball::bullet_detail
