#include "contact_counter.h"

#include <box2d/b2_body.h>
#include <box2d/b2_contact.h>
#include <box2d/b2_fixture.h>

#include "seam_contacts.h"

namespace fooball::box2d_detail {

namespace {

bool touchesWall(const b2Contact& contact) {
  return contact.GetFixtureA()->GetBody()->GetType() == b2_staticBody ||
         contact.GetFixtureB()->GetBody()->GetType() == b2_staticBody;
}

}  // namespace

void ContactCounter::BeginContact(b2Contact* contact) {
  if (!touchesWall(*contact)) {
    ++ballCollisions;
    return;
  }
  b2Body* first = contact->GetFixtureA()->GetBody();  // GetUserData() is not const in 2.4.1
  b2Body* second = contact->GetFixtureB()->GetBody();
  const bool firstIsWall = first->GetType() == b2_staticBody;
  b2Body* wall = firstIsWall ? first : second;
  b2Body* ball = firstIsWall ? second : first;
  const auto bit = static_cast<common::WallBit>(wall->GetUserData().pointer);
  wallCollisions += common::touchWall(touches_[ball->GetUserData().pointer], bit);
}

void ContactCounter::releaseWalls(std::span<b2Body* const> balls, const Box& box) {
  for (std::size_t i = 0; i < touches_.size(); ++i) {
    if (touches_[i] == 0) continue;
    const b2Body& ball = *balls[i];
    const b2Vec2& p = ball.GetPosition();
    const double radius = static_cast<double>(ball.GetFixtureList()->GetShape()->m_radius);
    touches_[i] = common::stillTouching(
        touches_[i], {static_cast<double>(p.x), static_cast<double>(p.y)}, radius, box);
  }
}

void ContactCounter::PreSolve(b2Contact* contact, const b2Manifold* /*oldManifold*/) {
  disableWallCornerContact(*contact);
}

void ContactCounter::PostSolve(b2Contact* contact, const b2ContactImpulse* impulse) {
  if (!touchesWall(*contact)) return;
  for (int32 point = 0; point < impulse->count; ++point) {
    wallImpulse += static_cast<double>(impulse->normalImpulses[point]);
  }
}

}  // namespace fooball::box2d_detail
