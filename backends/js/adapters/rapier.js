'use strict';
// Rapier 2D (npm @dimforge/rapier2d-compat, WebAssembly) as its users set it up for restitution 1
// (DESIGN.md, "Engines as their users set them up"); the option `version` picks one of the two
// releases installed side by side under npm aliases (package.json). Per setting:
// - restitution 1 and friction 0 on balls and walls, with the combine rules that give them
//   (restitution Max, friction Min: 1 and 0 whatever the other collider says);
// - rotations locked (RigidBodyDesc.lockRotations), linear and angular damping 0, sleeping off
//   (setCanSleep(false)); FooBall's drag is kick.js's;
// - mass set on the ball's collider (ColliderDesc.setMass), the scene's kg;
// - continuous collision off, as a new body has it (option `ccd`);
// - deeper knobs keep Rapier's defaults and are options named after its integration parameters:
//   numSolverIterations 4, numInternalPgsIterations 1, and the contacts' natural frequency
//   (contact_natural_frequency, 30 Hz; 0 here leaves the release's own). Rapier has no public
//   restitution threshold. Its soft contacts (a spring of that frequency pushing overlaps apart,
//   and restitution applied only to the approach it sees) are what change its energy
//   (docs/accuracy.md).
// - a ball whose centre has passed a wall that is on is brought back, mirrored inside with its
//   normal speed reversed (containBalls), as the matter adapter does: without continuous
//   collision a small fast ball can end a step beyond a wall's face, which the backend contract
//   forbids.
// Metres, y up, as FooBall's: Rapier's lengthUnit stays 1.

const fs = require('fs');
const path = require('path');
const {kickVelocities} = require('./kick');
const {WALL_BITS, WallImpulse, WallContacts, wallBoxes, mirrorInside} = require('./walls');

const VERSIONS = ['0.21.0', '0.19.3'];  // the option's choices, in the C++ side's order
const BALL = 6;
const BALLS_GROUP = 0x0001;
const WALLS_GROUP = 0x0002;

/// The version in an installed package's package.json (which its "exports" do not let require()).
function packageVersion(name) {
  const file = path.join(__dirname, '..', 'node_modules', name, 'package.json');
  return JSON.parse(fs.readFileSync(file, 'utf8')).version;
}

async function create() {
  const releases = {};  // version → its module, initialised when a run first asks for it

  let R = null;
  let world = null;
  let queue = null;
  let bodies = [];
  let masses = new Float64Array(0);
  let radii = new Float64Array(0);  // m, for the wall rule's release (walls.js)
  let colliderBall = new Map();  // collider handle → ball index, or −WALL_BITS[side] for a wall
  let walls = {};                // side → collider
  let wallBody = null;
  const wallContacts = new WallContacts();
  let settings = {};
  let scene = null;
  let velocities = new Float64Array(0);
  let wallImpulse = new WallImpulse(0);
  let counters = null;

  function groups(membership, filter) { return (membership << 16) | filter; }

  function ballCollider(def, index) {
    const desc = R.ColliderDesc.ball(def[4])
                     .setRestitution(1)
                     .setFriction(0)
                     .setRestitutionCombineRule(R.CoefficientCombineRule.Max)
                     .setFrictionCombineRule(R.CoefficientCombineRule.Min)
                     .setMass(def[5])
                     .setActiveEvents(R.ActiveEvents.COLLISION_EVENTS)
                     .setCollisionGroups(groups(BALLS_GROUP, WALLS_GROUP |
                                                (scene.world.ballCollisions ? BALLS_GROUP : 0)));
    const collider = world.createCollider(desc, bodies[index]);
    colliderBall.set(collider.handle, index);
    return collider;
  }

  function addBall(def, index) {
    const desc = R.RigidBodyDesc.dynamic()
                     .setTranslation(def[0], def[1])
                     .setLinvel(def[2], def[3])
                     .lockRotations()
                     .setLinearDamping(0)
                     .setAngularDamping(0)
                     .setCanSleep(false)
                     .setCcdEnabled(settings.ccd);
    bodies[index] = world.createRigidBody(desc);
    ballCollider(def, index);
  }

  function syncWalls() {
    const shapes = wallBoxes(scene.width, scene.height, scene.balls);
    for (const side of Object.keys(shapes)) {
      const on = scene.world.walls[side];
      if (on && !walls[side]) {
        const [x, y, hx, hy] = shapes[side];
        const desc = R.ColliderDesc.cuboid(hx, hy)
                         .setTranslation(x, y)
                         .setRestitution(1)
                         .setFriction(0)
                         .setRestitutionCombineRule(R.CoefficientCombineRule.Max)
                         .setFrictionCombineRule(R.CoefficientCombineRule.Min)
                         .setCollisionGroups(groups(WALLS_GROUP, BALLS_GROUP));
        walls[side] = world.createCollider(desc, wallBody);
        colliderBall.set(walls[side].handle, -WALL_BITS[side]);
      } else if (!on && walls[side]) {
        colliderBall.delete(walls[side].handle);
        world.removeCollider(walls[side], false);
        delete walls[side];
        wallContacts.clear();
      }
    }
  }

  function onCollision(handleA, handleB, started) {
    const a = colliderBall.get(handleA);
    const b = colliderBall.get(handleB);
    if (a !== undefined && b !== undefined) wallContacts.event(a, b, started, counters);
  }

  /// Brings back every ball whose centre is beyond a wall that is on; returns how many.
  function containBalls() {
    let brought = 0;
    for (const body of bodies) {
      const p = body.translation();
      const v = body.linvel();
      const back = mirrorInside(p.x, p.y, v.x, v.y, scene.width, scene.height, scene.world.walls);
      if (!back) continue;
      body.setTranslation({x: back[0], y: back[1]}, true);
      body.setLinvel({x: back[2], y: back[3]}, true);
      ++brought;
    }
    return brought;
  }

  function readVelocities() {
    for (let i = 0; i < bodies.length; ++i) {
      const v = bodies[i].linvel();
      velocities[2 * i] = v.x;
      velocities[2 * i + 1] = v.y;
    }
  }

  return {
    version: VERSIONS.map((v) => 'rapier2d ' + packageVersion('rapier2d-' + v)).join(', '),

    async prepare(options) {
      const version = VERSIONS[options.version];
      if (!releases[version]) {
        const module = require('rapier2d-' + version);
        await module.init();
        releases[version] = module;
      }
    },

    load(nextScene, options, sceneCounters) {
      settings = {
        version: VERSIONS[options.version],
        numSolverIterations: options.num_solver_iterations,
        numInternalPgsIterations: options.num_internal_pgs_iterations,
        contactNaturalFrequency: options.contact_natural_frequency,
        ccd: options.ccd !== 0,
      };
      counters = sceneCounters;
      scene = nextScene;
      if (world) world.free();
      R = releases[settings.version];
      world = new R.World({x: scene.world.gravity[0], y: scene.world.gravity[1]});
      const parameters = world.integrationParameters;
      parameters.numSolverIterations = settings.numSolverIterations;
      parameters.numInternalPgsIterations = settings.numInternalPgsIterations;
      if (settings.contactNaturalFrequency > 0) {
        parameters.contact_natural_frequency = settings.contactNaturalFrequency;
      }
      if (queue) queue.free();
      queue = new R.EventQueue(true);
      const n = scene.balls.length / BALL;
      bodies = new Array(n);
      masses = new Float64Array(n);
      radii = new Float64Array(n);
      colliderBall = new Map();
      wallContacts.clear();
      walls = {};
      wallBody = world.createRigidBody(R.RigidBodyDesc.fixed());
      for (let i = 0; i < n; ++i) {
        addBall(scene.balls.subarray(BALL * i, BALL * (i + 1)), i);
        masses[i] = scene.balls[BALL * i + 5];
        radii[i] = scene.balls[BALL * i + 4];
      }
      syncWalls();
      velocities = new Float64Array(2 * n);
      wallImpulse = new WallImpulse(n);
    },

    setWorld(next) {
      const collisionsChanged = next.ballCollisions !== scene.world.ballCollisions;
      scene.world = next;
      world.gravity = {x: next.gravity[0], y: next.gravity[1]};
      syncWalls();
      if (collisionsChanged) {
        const filter = WALLS_GROUP | (next.ballCollisions ? BALLS_GROUP : 0);
        for (const body of bodies) {
          body.collider(0).setCollisionGroups(groups(BALLS_GROUP, filter));
        }
      }
    },

    setBall(index, def) {
      const body = bodies[index];
      const old = body.collider(0);
      colliderBall.delete(old.handle);
      world.removeCollider(old, false);
      wallContacts.forget(index);
      body.setTranslation({x: def[0], y: def[1]}, true);
      body.setLinvel({x: def[2], y: def[3]}, true);
      ballCollider(def, index);
      masses[index] = def[5];
      radii[index] = def[4];
    },

    step(dt, forces, stepCounters) {
      counters = stepCounters;
      readVelocities();
      if (kickVelocities(velocities, masses, dt, forces, scene.world.airResistance, counters)) {
        for (let i = 0; i < bodies.length; ++i) {
          bodies[i].setLinvel({x: velocities[2 * i], y: velocities[2 * i + 1]}, true);
        }
      }
      wallImpulse.remember(velocities);
      world.timestep = dt;
      world.step(queue);
      counters.engineSteps += 1;
      counters.ballsBroughtBack += containBalls();
      wallContacts.beginStep();
      queue.drainCollisionEvents(onCollision);
      const charge = (i) => {
        const v = bodies[i].linvel();
        counters.wallImpulse += wallImpulse.charge(i, masses[i], v.x, v.y, scene.world.gravity, dt);
      };
      wallContacts.forEachCharged(charge);
      const centre = (i) => {
        const p = bodies[i].translation();
        return [p.x, p.y];
      };
      wallContacts.walls.release(centre, (i) => radii[i], scene.width, scene.height);
    },

    readState(out) {
      for (let i = 0; i < bodies.length; ++i) {
        const p = bodies[i].translation();
        const v = bodies[i].linvel();
        out[4 * i] = p.x;
        out[4 * i + 1] = p.y;
        out[4 * i + 2] = v.x;
        out[4 * i + 3] = v.y;
      }
    },
  };
}

module.exports = {create};
