'use strict';
// matter.js 0.20.0 as its users set it up for restitution 1 (DESIGN.md, "Engines as their
// users set them up"). Per setting, what is set and why:
// - restitution 1 on balls and walls (a pair takes the larger of the two: Pair.update);
// - friction, frictionStatic, frictionAir 0 (FooBall's drag is kick.js's, not frictionAir);
// - inertia Infinity: rotation locked, the documented way (Body.setInertia);
// - enableSleeping false (its default);
// - circles are what Bodies.circle makes: polygons of up to 25 sides, as users get them;
// - deeper knobs keep matter's defaults and are options: positionIterations 6,
//   velocityIterations 4, Resolver._restingThresh 2 (a private field: below that normal speed
//   a contact is solved as resting, with a clamped accumulated impulse that never bounces back
//   fully; 0 makes every hit elastic), and each body's slop 0.05 px.
//
// - a ball whose centre has passed a wall that is on is brought back, mirrored inside with its
//   normal speed reversed (containBalls): matter.js has no continuous collision, and a fast ball
//   can end a step beyond a wall's face, which the backend contract forbids (its users see the
//   same ball pushed out later by the position solver, from inside the 1 m thick wall).
//
// Scale: 64 pixels per metre, y down, matter's clock in milliseconds. matter.js is tuned in
// pixels (slop 0.05 px, resting threshold 2 px per 1/60 s frame, circles of 10 to 25 sides for
// radii of 10 to 25 px, Engine._deltaMax one frame): its examples run bodies of 10–80 px in
// an 800 × 600 canvas. 64 px/m puts FooBall's 16 × 9 m box at 1024 × 576 px and its 0.1–0.5 m
// balls at 6–32 px, where its users' scenes are; a power of two, so positions convert to
// pixels and back exactly. Its velocities are pixels per 1/60 s frame (Body._baseDelta).

const Matter = require('matter-js');
const {kickVelocities} = require('./kick');
const {WALL_BITS, WallImpulse, WallTouches} = require('./walls');

const PIXELS_PER_METRE = 64;
const BALL = 6;  // doubles per ball in a scene

function create() {
  const {Engine, Bodies, Body, Composite, Events, Resolver, Common} = Matter;
  // m/s → matter's px per frame
  const velocityScale = PIXELS_PER_METRE * (Common._baseDelta / 1000);

  let engine = null;
  let balls = [];  // Body per scene index
  let masses = new Float64Array(0);
  let radii = new Float64Array(0);  // m, for the wall rule's release (walls.js)
  const wallTouches = new WallTouches();
  let walls = {};  // side → Body, present only while in the world
  let world = null;
  let box = {width: 0, height: 0};
  let wallThickness = 1;  // m
  let settings = {};
  let velocities = new Float64Array(0);
  let wallImpulse = new WallImpulse(0);
  let counters = null;

  function ballBody(def, index) {
    const body = Bodies.circle(def[0] * PIXELS_PER_METRE, -def[1] * PIXELS_PER_METRE,
                               def[4] * PIXELS_PER_METRE, {
                                 restitution: 1,
                                 friction: 0,
                                 frictionStatic: 0,
                                 frictionAir: 0,
                                 inertia: Infinity,
                                 slop: settings.slop,
                                 collisionFilter: {group: world.ballCollisions ? 0 : -1},
                               });
    Body.setMass(body, def[5]);  // kg: only ratios of masses matter to its solver
    Body.setInertia(body, Infinity);
    Body.setVelocity(body, {x: def[2] * velocityScale, y: -def[3] * velocityScale});
    body.fooballIndex = index;
    return body;
  }

  function wallBody(side) {
    const t = wallThickness;
    const {width, height} = box;
    // Each wall overlaps the corners, so no ball leaks between two walls.
    const centre = {
      left: [-t / 2, height / 2, t, height + 2 * t],
      right: [width + t / 2, height / 2, t, height + 2 * t],
      bottom: [width / 2, -t / 2, width + 2 * t, t],
      top: [width / 2, height + t / 2, width + 2 * t, t],
    }[side];
    const body = Bodies.rectangle(centre[0] * PIXELS_PER_METRE, -centre[1] * PIXELS_PER_METRE,
                                  centre[2] * PIXELS_PER_METRE, centre[3] * PIXELS_PER_METRE, {
                                    isStatic: true,
                                    restitution: 1,
                                    friction: 0,
                                    frictionStatic: 0,
                                    slop: settings.slop,
                                  });
    body.fooballIndex = -WALL_BITS[side];
    return body;
  }

  function syncWalls() {
    for (const side of ['left', 'right', 'bottom', 'top']) {
      if (world.walls[side] && !walls[side]) {
        walls[side] = wallBody(side);
        Composite.add(engine.world, walls[side]);
      } else if (!world.walls[side] && walls[side]) {
        Composite.remove(engine.world, walls[side]);
        delete walls[side];
      }
    }
  }

  function setGravity() {
    // matter's gravity accelerates by gravity.{x,y} · scale px/ms² (Engine._bodiesApplyGravity,
    // Body.update): g m/s² is g · 64 · 1e-6 px/ms².
    engine.gravity.scale = 0.001;
    engine.gravity.x = world.gravity[0] * PIXELS_PER_METRE * 1e-3;
    engine.gravity.y = -world.gravity[1] * PIXELS_PER_METRE * 1e-3;
  }

  /// A contact that begins between two balls is a ball collision; with a wall (fooballIndex
  /// −WALL_BITS[side]) a wall collision by the rule of WallTouches (walls.js).
  function countCollisions(event) {
    for (const pair of event.pairs) {
      const a = pair.bodyA.fooballIndex;
      const b = pair.bodyB.fooballIndex;
      if (a >= 0 && b >= 0) {
        counters.ballCollisions += 1;
      } else {
        counters.wallCollisions += wallTouches.touch(a >= 0 ? a : b, -(a >= 0 ? b : a));
      }
    }
  }

  /// Brings back every ball whose centre is beyond a wall that is on (see the top); returns how
  /// many. Each is a wall bounce the contact events may not have seen.
  function containBalls() {
    const width = box.width * PIXELS_PER_METRE;
    const height = box.height * PIXELS_PER_METRE;  // y runs from 0 down to −height
    let brought = 0;
    for (const body of balls) {
      let {x, y} = body.position;
      let {x: vx, y: vy} = body.velocity;
      if (world.walls.left && x < 0) [x, vx] = [-x, Math.abs(vx)];
      if (world.walls.right && x > width) [x, vx] = [2 * width - x, -Math.abs(vx)];
      if (world.walls.top && y < -height) [y, vy] = [-2 * height - y, Math.abs(vy)];
      if (world.walls.bottom && y > 0) [y, vy] = [-y, -Math.abs(vy)];
      if (x === body.position.x && y === body.position.y) continue;
      Body.setPosition(body, {x, y});
      Body.setVelocity(body, {x: vx, y: vy});
      ++brought;
    }
    return brought;
  }

  function readVelocities() {
    for (let i = 0; i < balls.length; ++i) {
      velocities[2 * i] = balls[i].velocity.x / velocityScale;
      velocities[2 * i + 1] = -balls[i].velocity.y / velocityScale;
    }
  }

  return {
    version: Matter.version,

    load(scene, options, sceneCounters) {
      settings = {
        positionIterations: options.position_iterations,
        velocityIterations: options.velocity_iterations,
        restingThreshold: options.resting_thresh,
        slop: options.slop,
      };
      counters = sceneCounters;
      world = scene.world;
      box = {width: scene.width, height: scene.height};
      Resolver._restingThresh = settings.restingThreshold;
      engine = Engine.create({
        positionIterations: settings.positionIterations,
        velocityIterations: settings.velocityIterations,
        enableSleeping: false,
      });
      setGravity();
      Events.on(engine, 'collisionStart', countCollisions);
      const n = scene.balls.length / BALL;
      let largest = 0;  // m
      masses = new Float64Array(n);
      radii = new Float64Array(n);
      wallTouches.clear();
      balls = new Array(n);
      for (let i = 0; i < n; ++i) {
        const def = scene.balls.subarray(BALL * i, BALL * (i + 1));
        balls[i] = ballBody(def, i);
        masses[i] = def[5];
        radii[i] = def[4];
        largest = Math.max(largest, def[4]);
      }
      Composite.add(engine.world, balls);
      // Thick walls, as matter's examples build them (50 px and more), so a fast ball's step
      // ends inside the wall rather than beyond it: matter.js has no continuous collision.
      wallThickness = Math.max(1, 4 * largest);
      walls = {};
      syncWalls();
      velocities = new Float64Array(2 * n);
      wallImpulse = new WallImpulse(n);
    },

    setWorld(next) {
      const collisionsChanged = next.ballCollisions !== world.ballCollisions;
      world = next;
      setGravity();
      syncWalls();
      if (collisionsChanged) {
        for (const body of balls) body.collisionFilter.group = world.ballCollisions ? 0 : -1;
      }
    },

    setBall(index, def) {
      Composite.remove(engine.world, balls[index]);
      balls[index] = ballBody(def, index);
      masses[index] = def[5];
      radii[index] = def[4];
      wallTouches.forget(index);
      Composite.add(engine.world, balls[index]);
    },

    step(dt, forces, stepCounters) {
      counters = stepCounters;
      readVelocities();
      if (kickVelocities(velocities, masses, dt, forces, world.airResistance, counters)) {
        for (let i = 0; i < balls.length; ++i) {
          Body.setVelocity(balls[i], {x: velocities[2 * i] * velocityScale,
                                      y: -velocities[2 * i + 1] * velocityScale});
        }
      }
      wallImpulse.remember(velocities);
      Engine.update(engine, dt * 1000);
      counters.engineSteps += 1;
      counters.ballsBroughtBack += containBalls();
      for (const pair of engine.pairs.list) {
        if (!pair.isActive) continue;
        const a = pair.bodyA.fooballIndex;
        const b = pair.bodyB.fooballIndex;
        if (a >= 0 && b >= 0) continue;
        const i = a >= 0 ? a : b;
        const v = balls[i].velocity;
        counters.wallImpulse += wallImpulse.charge(i, masses[i], v.x / velocityScale,
                                                   -v.y / velocityScale, world.gravity, dt);
      }
      const centre = (i) => [balls[i].position.x / PIXELS_PER_METRE,
                             -balls[i].position.y / PIXELS_PER_METRE];
      wallTouches.release(centre, (i) => radii[i], box.width, box.height);
    },

    readState(out) {
      for (let i = 0; i < balls.length; ++i) {
        const body = balls[i];
        out[4 * i] = body.position.x / PIXELS_PER_METRE;
        out[4 * i + 1] = -body.position.y / PIXELS_PER_METRE;
        out[4 * i + 2] = body.velocity.x / velocityScale;
        out[4 * i + 3] = -body.velocity.y / velocityScale;
      }
    },

  };
}

module.exports = {create: async () => create()};
