#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "common/cell_lists.h"
#include "contact_memory.h"
#include "fooball/backend.h"
#include "fooball/scene.h"
#include "pair_contacts.h"
#include "particles.h"
#include "wall_contacts.h"

namespace fooball::xpbd {

/// Small-steps extended position-based dynamics (Macklin et al., "Small Steps in Physics
/// Simulation", SCA 2019; Müller et al., "Detailed Rigid Body Simulation with Extended Position
/// Based Dynamics", 2020) for frictionless balls, without the Backend interface around it.
/// Per substep of h = dt/substeps:
/// 1. predict: x_prev = x; v ← e^{−c·h}·v (drag, exact decay); v += h·g; x += h·v;
/// 2. find the overlapping pairs on the predicted centres (grid broadphase);
/// 3. `iterations` times: project the pairs, then the walls (Gauss–Seidel, compliance 0);
/// 4. v = (x − x_prev)/h for every ball a constraint moved (the others keep v exactly: the same
///    value without the rounding of a difference of nearby positions);
/// 5. the velocity pass, restitution e = 1 from the pre-solve normal velocity (Müller 2020
///    §3.6), pairs then walls, `iterations` times. One pass is Müller's; a ball with several
///    contacts in one substep needs more for all the restitution targets to hold together, and
///    then a substep of approaching contacts is a reflection that keeps the energy (measured on
///    the gas preset over 20 s: −12% with one pass, −0.17% with four; docs/performance.md).
/// External forces act as an impulse at the start of the step (Backend::step).
///
/// Energy: semi-implicit Euler keeps free flight on a parabola (the reported energy swings by
/// m·g·h·v/2 about a conserved one, no drift), and a lone contact leaves with the normal speed
/// it came in with. Energy is lost where a wall contact is found late under gravity (the ball is
/// put back at the wall with the speed of a whole substep's fall: up to m·|g|·h·u per bounce),
/// and where a contact that was not approaching is projected (its normal velocity is set to 0,
/// the min(−v̄_n, 0) of the restitution rule); it moves either way where several contacts share a
/// ball in one substep and the passes do not converge. docs/accuracy.md has the measurements.
///
/// Walls are projected last in every iteration and the velocity passes move no ball, so every
/// substep ends with every ball inside the walls that are on, whatever the pairs asked.
class XpbdWorld {
 public:
  /// Replaces the balls, box and world; zeroes the counters.
  void load(std::span<const BallDef> balls, const Box& box, const WorldSettings& world);
  void setWorld(const WorldSettings& world) { world_ = world; }
  void setBall(std::size_t slot, const BallDef& ball);
  void setSubsteps(int substeps) { substeps_ = substeps; }
  void setIterations(int iterations) { iterations_ = iterations; }

  /// Advances by `dt` seconds; forces as in Backend::step.
  void step(double dt, std::span<const Vec2> forces);

  const Particles& particles() const { return particles_; }
  const BackendCounters& counters() const { return counters_; }
  std::size_t memoryBytes() const;

 private:
  /// Balls are re-sorted by cell every this many substeps: often enough that neighbours stay
  /// close in memory, rarely enough that the move costs little next to the contact search.
  static constexpr std::uint32_t kSubstepsPerReorder = 16;

  /// At most one ball in this many is left out of the grid as oversized: a few big balls are
  /// cheap to meet one by one, many are not.
  static constexpr std::size_t kBallsPerOversized = 64;

  void layout();
  void substep(double h);
  void predict(double h);
  void deriveVelocities(double h);

  Box box_;
  WorldSettings world_;
  Particles particles_;
  common::CellLists grid_;
  PairContacts pairs_;
  ContactMemory memory_;
  std::vector<WallContact> wallContacts_;
  std::vector<std::uint32_t> wallRecordOf_;  ///< per ball and axis: its record in wallContacts_
  BackendCounters counters_;
  int substeps_ = 1;
  int iterations_ = 1;
  std::uint32_t substepCount_ = 0;  ///< since load, wrapping: the contact memory's clock
};

}  // namespace fooball::xpbd
