'use strict';
// What every adapter does before its engine's step, the same for all engines (DESIGN.md,
// "Backend contract"): the tool forces as an impulse forces[i]·dt at the start of the step, and
// FooBall's air resistance dv/dt = −c·v over the whole step, v·e^{−c·dt}, whose loss is summed
// exactly into the drag-loss counter. The engines' own damping stays 0, as their users set it
// up for restitution 1 (each damps differently: Rapier and Box2D v·1/(1+c·h), matter.js
// v·(1 − c·h) per frame), so the energy budget books the same drag for every engine.
//
// `velocities` is a Float64Array(2 n) of the engine's velocities in m/s, filled by the adapter;
// `masses` (kg) in scene order. Changes `velocities` in place and returns whether any changed.

function kickVelocities(velocities, masses, dt, forces, airResistance, counters) {
  const n = masses.length;
  if (forces) {
    for (let i = 0; i < n; ++i) {
      velocities[2 * i] += forces[2 * i] * (dt / masses[i]);
      velocities[2 * i + 1] += forces[2 * i + 1] * (dt / masses[i]);
    }
  }
  if (airResistance > 0) {
    const factor = Math.exp(-airResistance * dt);
    const takenFraction = 1 - factor * factor;  // of ½m|v|², what the drag takes
    let loss = 0;                               // J
    for (let i = 0; i < n; ++i) {
      const vx = velocities[2 * i];
      const vy = velocities[2 * i + 1];
      loss += 0.5 * masses[i] * (vx * vx + vy * vy) * takenFraction;
      velocities[2 * i] = vx * factor;
      velocities[2 * i + 1] = vy * factor;
    }
    counters.dragLoss += loss;
  }
  return !!forces || airResistance > 0;
}

module.exports = {kickVelocities};
