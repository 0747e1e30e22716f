#include "wall_bodies.h"

#include <box2d/b2_polygon_shape.h>

#include <algorithm>
#include <cmath>

#include "collision_filter.h"
#include "common/wall_touches.h"
#include "elastic_fixture.h"

namespace fooball::box2d_detail {

namespace {

enum Side { kLeft, kRight, kBottom, kTop, kSideCount };

/// m. Why thick boxes rather than edges: continuous collision against static bodies stops most
/// fast balls at the surface, but not all (it gives up after b2_maxSubSteps, and position
/// correction can squeeze a crowded ball in). A ball whose centre crossed a thin wall is pushed
/// out on the far side and lost. Box2D pushes a ball inside a polygon out through the nearest
/// face, and a ball moves at most b2_maxTranslation per Box2D step, so with this thickness its
/// centre usually stays in the inner half and the nearest face is the one facing into the box.
/// Not always: a time-of-impact sub-step's position correction can move a ball further, and near
/// the end of a piece (and in the corners, where two slabs overlap) the nearest face is a piece's
/// end. The random invariants lost balls that way for good, so WallContainment
/// (wall_containment.h) puts back every ball Box2D leaves beyond a wall after each Box2D step.
constexpr float kWallThickness = 4.0f * b2_maxTranslation;

/// m. Box2D polygons carry a skin of b2_polygonRadius (1 cm) that collides like the surface
/// (b2_shape.h: polygons must keep it). Moving every inner face out by the skin puts the
/// surface balls bounce off exactly on the box edge instead of 1 cm inside it.
constexpr float kSkin = b2_polygonRadius;

/// m. The longest piece a slab is cut into along its wall. Box2D's broad phase is a bounding-box
/// tree: one slab as long as its side, with a box several metres thick, swells the boxes of the
/// tree nodes it joins until most of them cover the whole scene, and every ball's query then
/// descends into them (callgrind, 5'000 balls: a query cost 3× that of a scene with whole-side
/// edges). Square pieces keep every node's box local; pieces of 4–16 m cost within 3% of this.
constexpr float kPieceLength = kWallThickness;

/// An axis-aligned slab [x0,x1] × [y0,y1] (m). Corners are given directly rather than as
/// centre ± half-size, so the inner face is the float of the box edge plus the skin, rounded once.
b2PolygonShape slab(float x0, float y0, float x1, float y1) {
  const b2Vec2 corners[4] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  b2PolygonShape shape;
  shape.Set(corners, 4);
  return shape;
}

/// The slab of one side as [low, high] (m) along the wall and [inner, outer] across it (inner
/// may be the larger: the right and top walls face −x and −y). Every slab reaches a thickness
/// past the box's corners, so a ball cannot slip out where two walls meet.
struct SideSlab {
  bool alongX;  ///< the bottom and top walls run along x
  float low;
  float high;
  float inner;
  float outer;
};

SideSlab sideSlab(Side side, const Box& box) {
  const float width = static_cast<float>(box.width);
  const float height = static_cast<float>(box.height);
  const float low = -kSkin - kWallThickness;
  const float highX = width + kSkin + kWallThickness;
  const float highY = height + kSkin + kWallThickness;
  switch (side) {
    case kLeft:
      return {false, low, highY, -kSkin, low};
    case kRight:
      return {false, low, highY, width + kSkin, highX};
    case kBottom:
      return {true, low, highX, -kSkin, low};
    default:
      return {true, low, highX, height + kSkin, highY};
  }
}

/// Piece `index` of `count` equal pieces of the slab. Neighbours compute their shared end from
/// the same expression, so the pieces meet without a gap; the inner face is the slab's.
b2PolygonShape slabPiece(const SideSlab& whole, int index, int count) {
  const auto end = [&](int i) {  // m, along the wall
    if (i == count) return whole.high;
    return whole.low + (whole.high - whole.low) * static_cast<float>(i) / static_cast<float>(count);
  };
  const float across0 = std::min(whole.inner, whole.outer);
  const float across1 = std::max(whole.inner, whole.outer);
  return whole.alongX ? slab(end(index), across0, end(index + 1), across1)
                      : slab(across0, end(index), across1, end(index + 1));
}

common::WallBit wallBit(Side side) {
  constexpr common::WallBit bits[] = {common::kLeftWall, common::kRightWall, common::kBottomWall,
                                      common::kTopWall};
  return bits[side];
}

b2Body* createWall(b2World& world, Side side, const Box& box) {
  b2BodyDef def;  // static, at the origin: the slab's vertices are world coordinates
  def.userData.pointer = wallBit(side);  // the contact counter's: which wall
  b2Body* body = world.CreateBody(&def);
  const SideSlab whole = sideSlab(side, box);
  const int pieces = static_cast<int>(std::ceil((whole.high - whole.low) / kPieceLength));
  for (int piece = 0; piece < pieces; ++piece) {
    const b2PolygonShape shape = slabPiece(whole, piece, pieces);
    const b2FixtureDef fixture = elasticFixtureDef(shape, 0.0f, wallFilter());
    body->CreateFixture(&fixture);
  }
  return body;
}

}  // namespace

void WallBodies::sync(b2World& world, const Box& box, const Walls& walls) {
  const std::array<bool, 4> on = {walls.left, walls.right, walls.bottom, walls.top};
  for (int side = kLeft; side < kSideCount; ++side) {
    b2Body*& body = bodies_[side];
    if (on[side] && body == nullptr) {
      body = createWall(world, static_cast<Side>(side), box);
    } else if (!on[side] && body != nullptr) {
      world.DestroyBody(body);
      body = nullptr;
    }
  }
}

}  // namespace fooball::box2d_detail
