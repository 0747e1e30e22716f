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

module.exports = {WallImpulse};
