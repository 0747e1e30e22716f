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

module.exports = {WallImpulse, WallContacts};
