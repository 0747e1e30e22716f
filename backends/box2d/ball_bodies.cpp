#include "ball_bodies.h"

#include <box2d/b2_circle_shape.h>
#include <box2d/b2_fixture.h>

#include <numbers>

#include "collision_filter.h"
#include "elastic_fixture.h"

namespace fooball::box2d_detail {

namespace {

float densityOf(double radius, double mass) {
  return static_cast<float>(mass / (std::numbers::pi * radius * radius));
}

void createCircleFixture(b2Body& body, double radius, double mass, b2Filter filter) {
  b2CircleShape circle;
  circle.m_radius = static_cast<float>(radius);
  const b2FixtureDef def = elasticFixtureDef(circle, densityOf(radius, mass), filter);
  body.CreateFixture(&def);
}

}  // namespace

b2Body* createBallBody(b2World& world, const BallDef& ball, bool ballCollisions, bool bullet) {
  b2BodyDef def;
  def.type = b2_dynamicBody;
  def.position.Set(static_cast<float>(ball.position.x), static_cast<float>(ball.position.y));
  def.linearVelocity.Set(static_cast<float>(ball.velocity.x), static_cast<float>(ball.velocity.y));
  def.fixedRotation = true;
  def.allowSleep = false;
  def.bullet = bullet;
  b2Body* body = world.CreateBody(&def);
  createCircleFixture(*body, ball.radius, ball.mass, ballFilter(ballCollisions));
  return body;
}

void setBallShape(b2Body& body, double radius, double mass) {
  b2Fixture* fixture = body.GetFixtureList();
  if (fixture->GetShape()->m_radius == static_cast<float>(radius)) {
    fixture->SetDensity(densityOf(radius, mass));
    body.ResetMassData();
    return;
  }
  const b2Filter filter = fixture->GetFilterData();
  body.DestroyFixture(fixture);
  createCircleFixture(body, radius, mass, filter);
}

void setBallCollisions(b2Body& body, bool ballCollisions) {
  body.GetFixtureList()->SetFilterData(ballFilter(ballCollisions));
}

}  // namespace fooball::box2d_detail
