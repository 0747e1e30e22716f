#include "contact_counter.h"

#include <box2d/b2_body.h>
#include <box2d/b2_contact.h>
#include <box2d/b2_fixture.h>

namespace fooball::box2d_detail {

namespace {

bool touchesWall(const b2Contact& contact) {
  return contact.GetFixtureA()->GetBody()->GetType() == b2_staticBody ||
         contact.GetFixtureB()->GetBody()->GetType() == b2_staticBody;
}

}  // namespace

void ContactCounter::BeginContact(b2Contact* contact) {
  if (touchesWall(*contact)) {
    ++wallCollisions;
  } else {
    ++ballCollisions;
  }
}

void ContactCounter::PostSolve(b2Contact* contact, const b2ContactImpulse* impulse) {
  if (!touchesWall(*contact)) return;
  for (int32 point = 0; point < impulse->count; ++point) {
    wallImpulse += static_cast<double>(impulse->normalImpulses[point]);
  }
}

}  // namespace fooball::box2d_detail
