#include "wall_segments.h"

#include <cstdint>

#include "collision_filter.h"
#include "common/wall_touches.h"
#include "elastic_material.h"

namespace fooball::chipmunk_detail {

namespace {

enum Side { kLeft, kRight, kBottom, kTop, kSideCount };

cpShape* createWall(Space& space, Side side, const Box& box, double thickness) {
  const double t = thickness;
  const double w = box.width;
  const double h = box.height;
  cpVect a;
  cpVect b;
  switch (side) {
    case kLeft:
      a = cpv(-t, -t);
      b = cpv(-t, h + t);
      break;
    case kRight:
      a = cpv(w + t, -t);
      b = cpv(w + t, h + t);
      break;
    case kBottom:
      a = cpv(-t, -t);
      b = cpv(w + t, -t);
      break;
    default:
      a = cpv(-t, h + t);
      b = cpv(w + t, h + t);
      break;
  }
  cpShape* shape = space.add(cpSegmentShapeNew(cpSpaceGetStaticBody(space.get()), a, b, t));
  makeElastic(shape);
  cpShapeSetCollisionType(shape, kWallType);
  // Which wall, for the contact counter (contact_counter.h).
  constexpr common::WallBit bits[] = {common::kLeftWall, common::kRightWall, common::kBottomWall,
                                      common::kTopWall};
  cpShapeSetUserData(shape, reinterpret_cast<cpDataPointer>(std::uintptr_t{bits[side]}));
  cpShapeSetFilter(shape, wallFilter());
  return shape;
}

}  // namespace

void WallSegments::sync(Space& space, const Box& box, const Walls& walls, double thickness) {
  const std::array<bool, 4> on = {walls.left, walls.right, walls.bottom, walls.top};
  for (int side = kLeft; side < kSideCount; ++side) {
    cpShape*& shape = shapes_[side];
    if (on[side] && shape == nullptr) {
      shape = createWall(space, static_cast<Side>(side), box, thickness);
    } else if (!on[side] && shape != nullptr) {
      space.remove(shape);
      shape = nullptr;
    }
  }
}

}  // namespace fooball::chipmunk_detail
