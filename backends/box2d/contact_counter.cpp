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

/// Whether the ball of the ball–wall contact `contact` already touches another piece of the same
/// wall: sliding over the seam between two pieces, or landing on one, is not a new collision.
bool ballAlreadyTouchesWall(const b2Contact& contact) {
  const b2Body* first = contact.GetFixtureA()->GetBody();
  const b2Body* second = contact.GetFixtureB()->GetBody();
  const b2Body* wall = first->GetType() == b2_staticBody ? first : second;
  const b2Body* ball = wall == first ? second : first;
  for (const b2ContactEdge* edge = ball->GetContactList(); edge != nullptr; edge = edge->next) {
    if (edge->other == wall && edge->contact != &contact && edge->contact->IsTouching())
      return true;
  }
  return false;
}

}  // namespace

void ContactCounter::BeginContact(b2Contact* contact) {
  if (touchesWall(*contact)) {
    if (!ballAlreadyTouchesWall(*contact)) ++wallCollisions;
  } else {
    ++ballCollisions;
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
