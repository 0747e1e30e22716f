#include "raw_box2d_world.h"

#include <box2d/b2_body.h>
#include <box2d/b2_circle_shape.h>
#include <box2d/b2_edge_shape.h>
#include <box2d/b2_fixture.h>

#include <numbers>

namespace fooball::benchmarks {

namespace {

constexpr int kVelocityIterations = 8;  // the values Box2D's own testbed uses
constexpr int kPositionIterations = 3;

b2Vec2 toBox2d(Vec2 v) {
  return {static_cast<float>(v.x), static_cast<float>(v.y)};
}

void addWall(b2Body& ground, b2Vec2 from, b2Vec2 to) {
  b2EdgeShape edge;
  edge.SetTwoSided(from, to);
  b2FixtureDef fixture;
  fixture.shape = &edge;
  fixture.restitution = 1.0f;
  fixture.restitutionThreshold = 0.0f;
  ground.CreateFixture(&fixture);
}

}  // namespace

RawBox2dWorld::RawBox2dWorld(const Scene& scene)
    : world_(std::make_unique<b2World>(toBox2d(scene.world.gravity))) {
  const b2BodyDef groundDef;
  b2Body* ground = world_->CreateBody(&groundDef);
  const auto width = static_cast<float>(scene.box.width);
  const auto height = static_cast<float>(scene.box.height);
  const Walls& walls = scene.world.walls;
  if (walls.left) addWall(*ground, {0.0f, 0.0f}, {0.0f, height});
  if (walls.right) addWall(*ground, {width, 0.0f}, {width, height});
  if (walls.bottom) addWall(*ground, {0.0f, 0.0f}, {width, 0.0f});
  if (walls.top) addWall(*ground, {0.0f, height}, {width, height});

  for (const BallDef& ball : scene.balls) {
    b2BodyDef bodyDef;
    bodyDef.type = b2_dynamicBody;
    bodyDef.position = toBox2d(ball.position);
    bodyDef.linearVelocity = toBox2d(ball.velocity);
    b2Body* body = world_->CreateBody(&bodyDef);
    b2CircleShape circle;
    circle.m_radius = static_cast<float>(ball.radius);
    b2FixtureDef fixture;
    fixture.shape = &circle;
    fixture.density =
        static_cast<float>(ball.mass / (std::numbers::pi * ball.radius * ball.radius));
    fixture.restitution = 1.0f;
    fixture.restitutionThreshold = 0.0f;
    body->CreateFixture(&fixture);
  }
}

void RawBox2dWorld::step(double dt, int substeps) {
  const auto box2dStep = static_cast<float>(dt / substeps);
  for (int substep = 0; substep < substeps; ++substep)
    world_->Step(box2dStep, kVelocityIterations, kPositionIterations);
}

}  // namespace fooball::benchmarks
