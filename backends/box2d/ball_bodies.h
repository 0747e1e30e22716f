#pragma once

#include <box2d/b2_body.h>
#include <box2d/b2_world.h>

#include "fooball/scene.h"

namespace fooball::box2d_detail {

/// Creates a ball: a dynamic body with one circle fixture of density mass/(π r²), so Box2D's
/// mass is the scene's (to float precision). Only what a ball needs: fixedRotation (no angular
/// state to integrate or to take energy), no sleeping (a sleeping ball would freeze and then
/// ignore drag and tools), no damping until the step sets the drag coefficient.
b2Body* createBallBody(b2World& world, const BallDef& ball, bool ballCollisions, bool bullet);

/// Gives the ball radius `radius` (m) and mass `mass` (kg). The fixture is replaced only when the
/// radius changes (a new fixture starts new contacts); a mass change alone sets the density.
void setBallShape(b2Body& body, double radius, double mass);

/// Sets the ball's collision filter (ball–ball collisions on or off) and refilters its contacts.
void setBallCollisions(b2Body& body, bool ballCollisions);

}  // namespace fooball::box2d_detail
