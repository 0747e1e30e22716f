#pragma once

#include <vector>

#include "contact_processing.h"
#include "fooball/options.h"
#include "split_impulse.h"
#include "warm_starting.h"

namespace fooball::bullet_detail {

/// The Bullet backend's options as the step loop uses them: read once when an option changes,
/// never per step. Every default is Bullet's own, each knob named after Bullet's (DESIGN.md,
/// "Engines as their users set them up"); what each does to the energy is in the header named.
struct BulletSettings {
  /// Bullet steps per step(), each dt/substeps seconds. 1: a Bullet user steps
  /// stepSimulation(1/60) with its default fixed step of 1/60 s, one Bullet step a frame.
  int substeps = 1;
  int solverIterations = 10;  ///< btContactSolverInfo::m_numIterations (Bullet's default)
  /// m, btContactSolverInfo::m_splitImpulsePenetrationThreshold (split_impulse.h).
  double splitImpulsePenetrationThreshold = kDefaultSplitImpulsePenetrationThreshold;
  /// m, btCollisionObject::setContactProcessingThreshold on every body (contact_processing.h).
  double contactProcessingThreshold = kDefaultContactProcessingThreshold;
  /// btContactSolverInfo::m_warmstartingFactor, 0 to 1 (warm_starting.h).
  double warmStarting = kDefaultWarmstartingFactor;
};

/// The option specs the backend registers, with BulletSettings' defaults.
std::vector<OptionSpec> bulletOptionSpecs();

/// `options` must hold the specs of bulletOptionSpecs(); OptionSet has checked the ranges.
BulletSettings readBulletSettings(const OptionSet& options);

}  // namespace fooball::bullet_detail
