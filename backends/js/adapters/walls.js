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

/// Which balls touch a wall, kept from an engine's contact begin and end events (Rapier's
/// collision events, Box2D v3's contact touch events): a contact that begins between two balls is
/// a ball–ball collision, between a ball and a wall a wall bounce; a ball that met a wall in a
/// step or still touches one is charged its WallImpulse at the step's end.
class WallContacts {
  constructor() {
    this.touching = new Map();  // ball index → number of walls it touches
    this.met = new Set();       // balls with a wall contact beginning or ending in this step
  }

  /// A wall was removed: its end events will not come, so touches are recounted from the next
  /// begins.
  clear() { this.touching.clear(); }

  /// Ball `ball` was replaced (an edit): its contacts are new.
  forget(ball) { this.touching.delete(ball); }

  /// Call before the step's events.
  beginStep() { this.met.clear(); }

  /// A contact between `a` and `b` (ball indices, −1 for a wall) began or ended.
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
      counters.wallCollisions += 1;
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

module.exports = {WallImpulse, WallContacts, wallBoxes, mirrorInside};
