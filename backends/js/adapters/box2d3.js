'use strict';
// Box2D v3 (npm box2d3-wasm 5.2.0, WebAssembly) as its users set it up for restitution 1
// (DESIGN.md, "Engines as their users set them up"). Per setting:
// - the module loaded with pthreadCount 0: single-threaded WebAssembly, no workers (the run is
//   one of several sharing the cores, and results stay the same bits on every run);
// - restitution 1 and friction 0 on balls and walls (b2SurfaceMaterial); Box2D v3 mixes a pair's
//   restitution as the larger and its friction as the geometric mean: 1 and 0;
// - rotation locked (b2BodyDef.motionLocks.angularZ, v3's fixed rotation), linear and angular
//   damping 0 (their defaults), sleeping off (b2WorldDef.enableSleep); FooBall's drag is kick.js's;
// - the public restitution threshold (b2WorldDef.restitutionThreshold) 0: below it v3 applies no
//   restitution at all, and its default 1 m/s makes every slower hit inelastic (option
//   `restitution_threshold`);
// - mass: density m/(π r²) on the ball's circle, so Box2D's mass is the scene's kg (in float);
// - deeper knobs keep Box2D v3's defaults and are options (backends/box2d3/box2d3_backend.cpp):
//   4 sub-steps per step (b2World_Step's subStepCount, its samples' value), the soft contacts'
//   30 Hz and damping ratio 10 and their 3 m/s push-out speed (b2World_SetContactTuning), warm
//   starting on, continuous collision on. Its soft step, relax iterations and restitution pass
//   are what change its energy (docs/accuracy.md).
// - contact begin events (enableContactEvents) count ball–ball collisions and wall bounces;
//   end events say when a ball stops touching a wall, for the wall impulse (walls.js);
// - a ball whose centre has passed a wall that is on is brought back, mirrored inside with its
//   normal speed reversed (containBalls), as the other hosted engines do: with `continuous` off a
//   small fast ball can end a step beyond a wall's face, which the backend contract forbids.
// Metres, y up, as FooBall's; Box2D's lengthUnitsPerMeter stays 1.

const fs = require('fs');
const path = require('path');
const {kickVelocities} = require('./kick');
const {WallImpulse} = require('./walls');

const BALL = 6;
const BALLS_CATEGORY = 0x0001;
const WALLS_CATEGORY = 0x0002;

function packageVersion() {
  const file = path.join(__dirname, '..', 'node_modules', 'box2d3-wasm', 'package.json');
  return JSON.parse(fs.readFileSync(file, 'utf8')).version;
}

async function create() {
  // The package is an ES module only: import() it from this CommonJS host.
  const {default: factory} = await import('box2d3-wasm');
  const B = await factory({pthreadCount: 0});

  const vec = new B.b2Vec2(0, 0);  // reused for every vector handed to Box2D
  const identity = B.b2MakeRot(0);
  function setVec(x, y) {
    vec.x = x;
    vec.y = y;
  }
  let worldId = null;
  let bodies = [];                  // b2BodyId per scene index
  let shapes = [];                  // b2ShapeId per scene index
  let masses = new Float64Array(0);
  let shapeBall = new Map();        // b2ShapeId.index1 → ball index, or −1 for a wall
  let walls = {};                   // side → b2ShapeId
  let wallBody = null;
  let touchingWall = new Map();     // ball index → number of walls it touches
  const metWall = new Set();        // balls with a wall contact beginning or ending in this step
  let settings = {};
  let scene = null;
  let state = new Float64Array(0);  // x, y, vx, vy per ball, as Box2D has them now
  let stateFresh = false;           // false: `state` must be read from Box2D again
  let velocities = new Float64Array(0);
  let wallImpulse = new WallImpulse(0);
  let counters = null;

  function material() {
    const m = B.b2DefaultSurfaceMaterial();
    m.restitution = 1;
    m.friction = 0;
    return m;
  }

  function shapeDef(category, mask) {
    const def = B.b2DefaultShapeDef();
    def.material = material();
    def.enableContactEvents = true;
    const filter = def.filter;
    filter.categoryBits = category;
    filter.maskBits = mask;
    def.filter = filter;
    return def;
  }

  function ballMask() { return WALLS_CATEGORY | (scene.world.ballCollisions ? BALLS_CATEGORY : 0); }

  function ballShape(def, index) {
    const sd = shapeDef(BALLS_CATEGORY, ballMask());
    sd.density = def[5] / (Math.PI * def[4] * def[4]);
    const circle = new B.b2Circle();
    circle.radius = def[4];
    shapes[index] = B.b2CreateCircleShape(bodies[index], sd, circle);
    shapeBall.set(shapes[index].index1, index);
    circle.delete();
    sd.delete();
  }

  function addBall(def, index) {
    const bd = B.b2DefaultBodyDef();
    bd.type = B.b2BodyType.b2_dynamicBody;
    setVec(def[0], def[1]);
    bd.position = vec;
    setVec(def[2], def[3]);
    bd.linearVelocity = vec;
    const locks = bd.motionLocks;
    locks.angularZ = true;
    bd.motionLocks = locks;
    bd.linearDamping = 0;
    bd.angularDamping = 0;
    bd.enableSleep = false;
    bodies[index] = B.b2CreateBody(worldId, bd);
    bd.delete();
    ballShape(def, index);
  }

  function syncWalls() {
    const {width, height} = scene;
    let largest = 0;
    for (let i = 0; i < bodies.length; ++i) largest = Math.max(largest, scene.balls[BALL * i + 4]);
    const t = Math.max(1, 4 * largest);  // m: thick, so a fast ball's step ends inside it
    const boxes = {
      left: [-t / 2, height / 2, t / 2, height / 2 + t],
      right: [width + t / 2, height / 2, t / 2, height / 2 + t],
      bottom: [width / 2, -t / 2, width / 2 + t, t / 2],
      top: [width / 2, height + t / 2, width / 2 + t, t / 2],
    };
    for (const side of Object.keys(boxes)) {
      const on = scene.world.walls[side];
      if (on && !walls[side]) {
        const [x, y, hx, hy] = boxes[side];
        setVec(x, y);
        const box = B.b2MakeOffsetBox(hx, hy, vec, identity);
        const sd = shapeDef(WALLS_CATEGORY, BALLS_CATEGORY);
        walls[side] = B.b2CreatePolygonShape(wallBody, sd, box);
        shapeBall.set(walls[side].index1, -1);
        sd.delete();
        box.delete();
      } else if (!on && walls[side]) {
        shapeBall.delete(walls[side].index1);
        B.b2DestroyShape(walls[side], false);
        delete walls[side];
        touchingWall.clear();  // its end events will not come: recounted from the next begins
      }
    }
  }

  function onTouch(shapeA, shapeB, began) {
    const a = shapeBall.get(shapeA.index1);
    const b = shapeBall.get(shapeB.index1);
    if (a === undefined || b === undefined) return;
    if (a >= 0 && b >= 0) {
      if (began) counters.ballCollisions += 1;
      return;
    }
    const ball = a >= 0 ? a : b;
    if (ball < 0) return;
    metWall.add(ball);
    const touching = touchingWall.get(ball) || 0;
    if (began) {
      counters.wallCollisions += 1;
      touchingWall.set(ball, touching + 1);
    } else if (touching <= 1) {
      touchingWall.delete(ball);
    } else {
      touchingWall.set(ball, touching - 1);
    }
  }

  function drainContactEvents() {
    const events = B.b2World_GetContactEvents(worldId);
    for (let i = 0; i < events.beginCount; ++i) {
      const e = events.GetBeginEvent(i);
      onTouch(e.shapeIdA, e.shapeIdB, true);
    }
    for (let i = 0; i < events.endCount; ++i) {
      const e = events.GetEndEvent(i);
      onTouch(e.shapeIdA, e.shapeIdB, false);
    }
    events.delete();
  }

  /// Every ball's position and velocity into `state`, once per change.
  function readAll() {
    if (stateFresh) return;
    for (let i = 0; i < bodies.length; ++i) {
      const p = B.b2Body_GetPosition(bodies[i]);
      const v = B.b2Body_GetLinearVelocity(bodies[i]);
      state[4 * i] = p.x;
      state[4 * i + 1] = p.y;
      state[4 * i + 2] = v.x;
      state[4 * i + 3] = v.y;
      p.delete();
      v.delete();
    }
    stateFresh = true;
  }

  function setPosition(i, x, y) {
    setVec(x, y);
    B.b2Body_SetTransform(bodies[i], vec, identity);
  }

  function setVelocity(i, vx, vy) {
    setVec(vx, vy);
    B.b2Body_SetLinearVelocity(bodies[i], vec);
  }

  /// Brings back every ball whose centre is beyond a wall that is on; returns how many.
  function containBalls() {
    const {width, height} = scene;
    const on = scene.world.walls;
    let brought = 0;
    for (let i = 0; i < bodies.length; ++i) {
      const px = state[4 * i];
      const py = state[4 * i + 1];
      let [x, y, vx, vy] = [px, py, state[4 * i + 2], state[4 * i + 3]];
      if (on.left && x < 0) [x, vx] = [-x, Math.abs(vx)];
      if (on.right && x > width) [x, vx] = [2 * width - x, -Math.abs(vx)];
      if (on.bottom && y < 0) [y, vy] = [-y, Math.abs(vy)];
      if (on.top && y > height) [y, vy] = [2 * height - y, -Math.abs(vy)];
      if (x === px && y === py) continue;
      setPosition(i, x, y);
      setVelocity(i, vx, vy);
      ++brought;
    }
    if (brought > 0) stateFresh = false;  // read back as Box2D rounds them
    return brought;
  }

  return {
    version: 'box2d3-wasm ' + packageVersion(),

    load(nextScene, options, sceneCounters) {
      settings = {
        substeps: options.substeps,
        restitutionThreshold: options.restitution_threshold,
        contactHertz: options.contact_hertz,
        contactDampingRatio: options.contact_damping_ratio,
        pushOutSpeed: options.push_out_speed,
        warmStarting: options.warm_starting !== 0,
        continuous: options.continuous !== 0,
      };
      counters = sceneCounters;
      scene = nextScene;
      if (worldId) B.b2DestroyWorld(worldId);
      const def = B.b2DefaultWorldDef();
      setVec(scene.world.gravity[0], scene.world.gravity[1]);
      def.gravity = vec;
      def.enableSleep = false;
      def.restitutionThreshold = settings.restitutionThreshold;
      def.enableContinuous = settings.continuous;
      worldId = B.b2CreateWorld(def);
      def.delete();
      B.b2World_SetContactTuning(worldId, settings.contactHertz, settings.contactDampingRatio,
                                 settings.pushOutSpeed);
      B.b2World_EnableWarmStarting(worldId, settings.warmStarting);
      const n = scene.balls.length / BALL;
      bodies = new Array(n);
      shapes = new Array(n);
      masses = new Float64Array(n);
      shapeBall = new Map();
      touchingWall = new Map();
      walls = {};
      const wallDef = B.b2DefaultBodyDef();
      wallBody = B.b2CreateBody(worldId, wallDef);  // static, its default type
      wallDef.delete();
      for (let i = 0; i < n; ++i) {
        addBall(scene.balls.subarray(BALL * i, BALL * (i + 1)), i);
        masses[i] = scene.balls[BALL * i + 5];
      }
      syncWalls();
      state = new Float64Array(4 * n);
      stateFresh = false;
      velocities = new Float64Array(2 * n);
      wallImpulse = new WallImpulse(n);
    },

    setWorld(next) {
      const collisionsChanged = next.ballCollisions !== scene.world.ballCollisions;
      scene.world = next;
      setVec(next.gravity[0], next.gravity[1]);
      B.b2World_SetGravity(worldId, vec);
      syncWalls();
      if (collisionsChanged) {
        for (const shape of shapes) {
          const filter = B.b2Shape_GetFilter(shape);
          filter.maskBits = ballMask();
          B.b2Shape_SetFilter(shape, filter);
          filter.delete();
        }
      }
    },

    setBall(index, def) {
      shapeBall.delete(shapes[index].index1);
      B.b2DestroyShape(shapes[index], false);
      touchingWall.delete(index);
      setPosition(index, def[0], def[1]);
      setVelocity(index, def[2], def[3]);
      ballShape(def, index);
      masses[index] = def[5];
      stateFresh = false;
    },

    step(dt, forces, stepCounters) {
      counters = stepCounters;
      readAll();
      for (let i = 0; i < bodies.length; ++i) {
        velocities[2 * i] = state[4 * i + 2];
        velocities[2 * i + 1] = state[4 * i + 3];
      }
      if (kickVelocities(velocities, masses, dt, forces, scene.world.airResistance, counters)) {
        for (let i = 0; i < bodies.length; ++i) setVelocity(i, velocities[2 * i], velocities[2 * i + 1]);
      }
      wallImpulse.remember(velocities);
      B.b2World_Step(worldId, dt, settings.substeps);
      stateFresh = false;
      counters.engineSteps += 1;
      readAll();
      counters.ballsBroughtBack += containBalls();
      readAll();
      metWall.clear();
      drainContactEvents();
      const charge = (i) => {
        counters.wallImpulse += wallImpulse.charge(i, masses[i], state[4 * i + 2], state[4 * i + 3],
                                                   scene.world.gravity, dt);
      };
      metWall.forEach(charge);
      for (const i of touchingWall.keys()) charge(i);
    },

    readState(out) {
      readAll();
      out.set(state);
    },
  };
}

module.exports = {create};
