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
const {WALL_BITS, WallImpulse, WallContacts, wallBoxes, mirrorInside} = require('./walls');

const BALL = 6;
const BALLS_CATEGORY = 0x0001;
const WALLS_CATEGORY = 0x0002;

function packageVersion() {
  const file = path.join(__dirname, '..', 'node_modules', 'box2d3-wasm', 'package.json');
  return JSON.parse(fs.readFileSync(file, 'utf8')).version;
}

/// Every ball's state after a step, read straight out of the WebAssembly heap with typed-array
/// views: body by body through the bindings (each a few calls, an allocation and a copy) costs
/// more than the step itself at 10,000 balls (docs/performance.md).
/// - Positions: the step's body move events (b2World_GetBodyEvents), an array of
///   b2BodyMoveEvent {void* userData; b2Transform transform; b2BodyId bodyId; bool fellAsleep},
///   32 bytes each, one per awake body; the binding's b2BodyEvents copy {moveEvents, moveCount}
///   holds where it is.
/// - Velocities: the awake set's b2BodyState array (linearVelocity first), which no binding hands
///   out: found at each load by marking two balls' velocities and finding the marks in the memory
///   above the stack (its slots keep copies of the vectors handed over). Sleeping is
///   off and no body is added or removed until the next load, so it stays where it is, in the
///   order of the move events.
/// Each step checks what it relies on (the events' body ids in ball order, one ball's velocity
/// against b2Body_GetLinearVelocity, in turn) and fails the run with a clear error otherwise.
class HeapState {
  constructor(B, memory) {
    this.B = B;
    this.memory = memory;
    this.velocityBase = 0;  // byte address of ball 0's b2BodyState
    this.velocityStride = 0;
    this.checked = 0;  // the ball whose velocity the next step checks
    this.views = null;  // typed arrays over the memory's buffer, made again when it grows
  }

  /// Views of the whole memory as it is now.
  heap() {
    const buffer = this.memory.buffer;
    if (!this.views || this.views.bytes !== buffer.byteLength) {
      this.views = {bytes: buffer.byteLength, f32: new Float32Array(buffer),
                    i32: new Int32Array(buffer)};
    }
    return this.views;
  }

  floats() { return this.heap().f32; }

  /// Finds the b2BodyState array of the world just loaded; `state` holds the balls' velocities.
  locateVelocities(bodies, state, setVelocity, clearVector) {
    if (bodies.length === 0) return;
    const marks = [[-12345.6789, 9876.54321], [-23456.7891, 8765.43219]];
    const count = Math.min(2, bodies.length);
    for (let i = 0; i < count; ++i) setVelocity(i, marks[i][0], marks[i][1]);
    clearVector();  // the vector that handed them over holds no mark
    const f = this.floats();
    const mark = marks.map(([x, y]) => [Math.fround(x), Math.fround(y)]);
    const found = [];
    // Above the stack, whose slots keep copies of the last vectors handed over: in the memory
    // malloc hands out.
    const heapStart = (this.B.stackSave() + 3) >> 2;
    for (let k = heapStart; k + 1 < f.length && found.length < count; ++k) {
      const i = found.length;
      if (f[k] === mark[i][0] && f[k + 1] === mark[i][1]) found.push(4 * k);
    }
    for (let i = 0; i < count; ++i) setVelocity(i, state[4 * i + 2], state[4 * i + 3]);
    if (found.length < count || (count === 2 && found[1] <= found[0])) {
      throw new Error('box2d3: the balls\' velocities were not found in the WebAssembly heap');
    }
    this.velocityBase = found[0];
    this.velocityStride = count === 2 ? found[1] - found[0] : 0;
    this.checked = 0;
    const g = this.floats();
    for (let i = 0; i < bodies.length; ++i) {
      const at = (this.velocityBase + i * this.velocityStride) >> 2;
      if (g[at] !== state[4 * i + 2] || g[at + 1] !== state[4 * i + 3]) {
        throw new Error(`box2d3: ball ${i}'s velocity is not where the heap layout puts it`);
      }
    }
  }

  /// Every ball's x, y, vx, vy after a step into `state`.
  read(worldId, bodies, state) {
    const n = bodies.length;
    if (n === 0) return;
    const events = this.B.b2World_GetBodyEvents(worldId);
    const {f32: f, i32: ids} = this.heap();
    const moveEvents = ids[events.$$.ptr >> 2];
    const moveCount = ids[(events.$$.ptr >> 2) + 1];
    events.delete();
    if (moveCount !== n) {
      throw new Error(`box2d3: ${moveCount} body move events for ${n} balls`);
    }
    for (let i = 0; i < n; ++i) {
      const event = (moveEvents >> 2) + 8 * i;
      if (ids[event + 5] !== bodies[i].index1) {
        throw new Error(`box2d3: body move event ${i} is not ball ${i}'s`);
      }
      const velocity = (this.velocityBase + i * this.velocityStride) >> 2;
      state[4 * i] = f[event + 1];
      state[4 * i + 1] = f[event + 2];
      state[4 * i + 2] = f[velocity];
      state[4 * i + 3] = f[velocity + 1];
    }
    const i = this.checked;
    this.checked = (i + 1) % n;
    const v = this.B.b2Body_GetLinearVelocity(bodies[i]);
    const same = v.x === state[4 * i + 2] && v.y === state[4 * i + 3];
    v.delete();
    if (!same) throw new Error(`box2d3: ball ${i}'s velocity in the heap is not Box2D's`);
  }
}

async function create() {
  // The package is an ES module only: import() it from this CommonJS host.
  const {default: factory} = await import('box2d3-wasm');
  // Its own memory, as Emscripten's Module.wasmMemory (the package's defaults: 16 MiB, shared,
  // up to 2 GiB), so the views below always see its current buffer when it grows.
  const memory = new WebAssembly.Memory({initial: 256, maximum: 32768, shared: true});
  const B = await factory({pthreadCount: 0, wasmMemory: memory});
  const heap = new HeapState(B, memory);

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
  let radii = new Float64Array(0);  // m, for the wall rule's release (walls.js)
  let shapeBall = new Map();        // b2ShapeId.index1 → ball index, or −WALL_BITS[side] for a wall
  let walls = {};                   // side → b2ShapeId
  let wallBody = null;
  const wallContacts = new WallContacts();
  let settings = {};
  let scene = null;
  let state = new Float64Array(0);  // x, y, vx, vy per ball, as Box2D has them now
  let velocities = new Float64Array(0);
  let wallImpulse = new WallImpulse(0);
  let counters = null;

  function shapeDef(category, mask) {
    const def = B.b2DefaultShapeDef();
    const material = B.b2DefaultSurfaceMaterial();
    material.restitution = 1;
    material.friction = 0;
    def.material = material;  // a copy: the returned one is ours to delete
    material.delete();
    def.enableContactEvents = true;
    const filter = def.filter;  // a reference into def (the binding's), not a copy
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
    const boxes = wallBoxes(scene.width, scene.height, scene.balls);
    for (const side of Object.keys(boxes)) {
      const on = scene.world.walls[side];
      if (on && !walls[side]) {
        const [x, y, hx, hy] = boxes[side];
        setVec(x, y);
        const box = B.b2MakeOffsetBox(hx, hy, vec, identity);
        const sd = shapeDef(WALLS_CATEGORY, BALLS_CATEGORY);
        walls[side] = B.b2CreatePolygonShape(wallBody, sd, box);
        shapeBall.set(walls[side].index1, -WALL_BITS[side]);
        sd.delete();
        box.delete();
      } else if (!on && walls[side]) {
        shapeBall.delete(walls[side].index1);
        B.b2DestroyShape(walls[side], false);
        delete walls[side];
        wallContacts.clear();
      }
    }
  }

  function onTouch(shapeA, shapeB, began) {
    const a = shapeBall.get(shapeA.index1);
    const b = shapeBall.get(shapeB.index1);
    if (a !== undefined && b !== undefined) wallContacts.event(a, b, began, counters);
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

  /// Every ball's position and velocity into `state`, body by body through the bindings (at a
  /// load; a step reads them from the heap: HeapState).
  function readAll() {
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
  }

  /// What Box2D keeps of a ball's position and velocity just set: float.
  function keep(i, x, y, vx, vy) {
    state.set([Math.fround(x), Math.fround(y), Math.fround(vx), Math.fround(vy)], 4 * i);
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
    let brought = 0;
    for (let i = 0; i < bodies.length; ++i) {
      const back = mirrorInside(state[4 * i], state[4 * i + 1], state[4 * i + 2],
                                state[4 * i + 3], scene.width, scene.height, scene.world.walls);
      if (!back) continue;
      setPosition(i, back[0], back[1]);
      setVelocity(i, back[2], back[3]);
      keep(i, ...back);
      ++brought;
    }
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
      radii = new Float64Array(n);
      shapeBall = new Map();
      wallContacts.clear();
      walls = {};
      const wallDef = B.b2DefaultBodyDef();
      wallBody = B.b2CreateBody(worldId, wallDef);  // static, its default type
      wallDef.delete();
      for (let i = 0; i < n; ++i) {
        addBall(scene.balls.subarray(BALL * i, BALL * (i + 1)), i);
        masses[i] = scene.balls[BALL * i + 5];
        radii[i] = scene.balls[BALL * i + 4];
      }
      syncWalls();
      state = new Float64Array(4 * n);
      readAll();
      heap.locateVelocities(bodies, state, setVelocity, () => setVec(0, 0));
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
      wallContacts.forget(index);
      setPosition(index, def[0], def[1]);
      setVelocity(index, def[2], def[3]);
      ballShape(def, index);
      masses[index] = def[5];
      radii[index] = def[4];
      keep(index, def[0], def[1], def[2], def[3]);
    },

    step(dt, forces, stepCounters) {
      counters = stepCounters;
      for (let i = 0; i < bodies.length; ++i) {
        velocities[2 * i] = state[4 * i + 2];
        velocities[2 * i + 1] = state[4 * i + 3];
      }
      if (kickVelocities(velocities, masses, dt, forces, scene.world.airResistance, counters)) {
        for (let i = 0; i < bodies.length; ++i) setVelocity(i, velocities[2 * i], velocities[2 * i + 1]);
      }
      wallImpulse.remember(velocities);
      B.b2World_Step(worldId, dt, settings.substeps);
      counters.engineSteps += 1;
      heap.read(worldId, bodies, state);
      counters.ballsBroughtBack += containBalls();
      wallContacts.beginStep();
      drainContactEvents();
      const charge = (i) => {
        counters.wallImpulse += wallImpulse.charge(i, masses[i], state[4 * i + 2], state[4 * i + 3],
                                                   scene.world.gravity, dt);
      };
      wallContacts.forEachCharged(charge);
      const centre = (i) => [state[4 * i], state[4 * i + 1]];
      wallContacts.walls.release(centre, (i) => radii[i], scene.width, scene.height);
    },

    readState(out) {
      out.set(state);
    },
  };
}

module.exports = {create};
