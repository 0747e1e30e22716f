'use strict';
// Wall impulse for engines that do not hand out the impulses they apply (matter.js clears its
// cached impulse for every fast contact, Resolver.solveVelocity): each ball that touched a wall
// in the step is charged m·|v_after − v_before − g·dt|, its momentum change beyond gravity's. It
// is the wall's whole impulse for a ball that met only the wall in the step, and also holds
// what other balls gave it in the same step otherwise (a small overcount in a dense crowd).

class WallImpulse {
  constructor(n) {
    this.before = new Float64Array(2 * n);  // m/s, each ball's velocity at the step's start
    this.stamp = new Uint32Array(n);        // the step a ball was last charged in
    this.step = 0;
  }

  /// Call after the kick, before the engine's step.
  remember(velocities) { this.before.set(velocities); ++this.step; }

  /// Charges ball i once per step; `after` its velocity (m/s) now.
  charge(i, mass, afterX, afterY, gravity, dt) {
    if (this.stamp[i] === this.step) return 0;
    this.stamp[i] = this.step;
    const dx = afterX - this.before[2 * i] - gravity[0] * dt;
    const dy = afterY - this.before[2 * i + 1] - gravity[1] * dt;
    return mass * Math.hypot(dx, dy);
  }
}

/// The wall-collision rule of backends/common/wall_touches.h, which owns it (its constant and its
/// two functions); this is its twin for the engines in the Node.js host, and
/// tests/wall_count_test.cpp holds both to the same answers. A wall collision is one reversal of
/// a ball's approach to a wall: a contact with a wall the ball still touches (it has not left it
/// by a tenth of its radius since the wall last turned it back) is the collision it began, not a
/// new one, so a resting ball whose contact breaks and begins again counts once.
const WALL_RELEASE_FRACTION = 0.1;
const WALL_BITS = {left: 1, right: 2, bottom: 4, top: 8};

class WallTouches {
  constructor() {
    this.bits = new Map();  // ball index → the WALL_BITS of the walls it touches
  }

  clear() { this.bits.clear(); }
  forget(ball) { this.bits.delete(ball); }

  /// The wall `bit` turned ball `ball` back: 1 when that begins a collision, else 0.
  touch(ball, bit) {
    const touches = this.bits.get(ball) || 0;
    this.bits.set(ball, touches | bit);
    return (touches & bit) !== 0 ? 0 : 1;
  }

  /// Forgets the walls each ball has left; `centre(i)` is its [x, y] and `radius(i)` its radius
  /// (m, y up), in the box [0, width] × [0, height].
  release(centre, radius, width, height) {
    for (const [ball, touches] of this.bits) {
      const [x, y] = centre(ball);
      const reach = (1 + WALL_RELEASE_FRACTION) * radius(ball);  // m, centre to wall
      let kept = touches;
      if (x > reach) kept &= ~WALL_BITS.left;
      if (x < width - reach) kept &= ~WALL_BITS.right;
      if (y > reach) kept &= ~WALL_BITS.bottom;
      if (y < height - reach) kept &= ~WALL_BITS.top;
      if (kept === 0) {
        this.bits.delete(ball);
      } else {
        this.bits.set(ball, kept);
      }
    }
  }
}

/// Which balls touch a wall, kept from an engine's contact begin and end events (Rapier's
/// collision events, Box2D v3's contact touch events): a contact that begins between two balls is
/// a ball–ball collision, between a ball and a wall a wall bounce; a ball that met a wall in a
/// step or still touches one is charged its WallImpulse at the step's end. A contact that begins
/// with a wall is a wall collision by the rule of WallTouches.
class WallContacts {
  constructor() {
    this.touching = new Map();  // ball index → number of walls it touches
    this.met = new Set();       // balls with a wall contact beginning or ending in this step
    this.walls = new WallTouches();
  }

  /// A wall was removed: its end events will not come, so touches are recounted from the next
  /// begins.
  clear() {
    this.touching.clear();
    this.walls.clear();
  }

  /// Ball `ball` was replaced (an edit): its contacts are new.
  forget(ball) {
    this.touching.delete(ball);
    this.walls.forget(ball);
  }

  /// Call before the step's events.
  beginStep() { this.met.clear(); }

  /// A contact between `a` and `b` (ball indices, or −WALL_BITS[side] for a wall) began or ended.
  event(a, b, began, counters) {
    if (a >= 0 && b >= 0) {
      if (began) counters.ballCollisions += 1;
      return;
    }
    const ball = a >= 0 ? a : b;
    if (ball < 0) return;
    this.met.add(ball);
    const touching = this.touching.get(ball) || 0;
    if (began) {
      counters.wallCollisions += this.walls.touch(ball, -(a >= 0 ? b : a));
      this.touching.set(ball, touching + 1);
    } else if (touching <= 1) {
      this.touching.delete(ball);
    } else {
      this.touching.set(ball, touching - 1);
    }
  }

  /// Calls charge(i) for every ball that met or touches a wall in this step (WallImpulse charges a
  /// ball once a step).
  forEachCharged(charge) {
    this.met.forEach(charge);
    for (const i of this.touching.keys()) charge(i);
  }
}

/// The walls of a box [0, width] × [0, height] (y up) as boxes outside it, side → [centre x,
/// centre y, half width, half height] in m: thick (1 m, or 4 of the largest radii of the scene's
/// `balls`, 6 doubles each, radius 5th), so a fast ball's step ends inside one.
function wallBoxes(width, height, balls) {
  let largest = 0;
  for (let i = 4; i < balls.length; i += 6) largest = Math.max(largest, balls[i]);
  const t = Math.max(1, 4 * largest);
  return {
    left: [-t / 2, height / 2, t / 2, height / 2 + t],
    right: [width + t / 2, height / 2, t / 2, height / 2 + t],
    bottom: [width / 2, -t / 2, width / 2 + t, t / 2],
    top: [width / 2, height + t / 2, width / 2 + t, t / 2],
  };
}

/// A ball whose centre (x, y) has passed a wall that is on (`on`: side → bool), mirrored back
/// inside with its normal speed reversed: [x, y, vx, vy], or null when it is inside (y up).
function mirrorInside(x, y, vx, vy, width, height, on) {
  const [x0, y0] = [x, y];
  if (on.left && x < 0) [x, vx] = [-x, Math.abs(vx)];
  if (on.right && x > width) [x, vx] = [2 * width - x, -Math.abs(vx)];
  if (on.bottom && y < 0) [y, vy] = [-y, Math.abs(vy)];
  if (on.top && y > height) [y, vy] = [2 * height - y, -Math.abs(vy)];
  return x === x0 && y === y0 ? null : [x, y, vx, vy];
}

module.exports = {WALL_BITS, WallTouches, WallImpulse, WallContacts, wallBoxes, mirrorInside};
