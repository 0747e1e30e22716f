#include "seam_contacts.h"

#include <box2d/b2_body.h>
#include <box2d/b2_collision.h>
#include <box2d/b2_fixture.h>

namespace fooball::box2d_detail {

void disableWallCornerContact(b2Contact& contact) {
  const b2Body* first = contact.GetFixtureA()->GetBody();
  const b2Body* second = contact.GetFixtureB()->GetBody();
  if (first->GetType() != b2_staticBody && second->GetType() != b2_staticBody) return;
  // The manifold's normal is in the frame of the piece, a static body at the origin without
  // rotation (wall_bodies.cpp), so it is the world normal.
  const b2Vec2 normal = contact.GetManifold()->localNormal;
  if (normal.x != 0.0f && normal.y != 0.0f) contact.SetEnabled(false);
}

}  // namespace fooball::box2d_detail
