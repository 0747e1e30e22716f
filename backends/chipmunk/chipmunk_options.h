#pragma once

#include <vector>

#include "contact_slop.h"
#include "fooball/options.h"

namespace fooball::chipmunk_detail {

/// The Chipmunk backend's options as the step loop uses them: read once when an option changes,
/// never per step. The contact defaults and their measurements are in contact_slop.h, the
/// broad phases in broadphase.h.
struct ChipmunkSettings {
  /// Chipmunk steps per step(). 4, as the elastic and Box2D backends: Chipmunk has no
  /// continuous collision, so a substep's travel is a contact's overlap. Measured with 1 (quick
  /// grid): the failure map's packing and scale sweeps fail at every point, on overlap (a 1/60 s
  /// step at 3 m/s travels 0.25 r of a 0.2 m ball), and the `rain` preset loses 55% of its
  /// energy in 20 s (6% with 4). With 1 it carries about twice the balls (docs/performance.md).
  int substeps = 4;
  int iterations = 10;  ///< impulse-solver passes per Chipmunk step (Chipmunk's default)
  /// Overlap left alone by the position correction, as a fraction of the smallest ball radius.
  double collisionSlop = kDefaultSlopFraction;
  /// Fraction of an overlap (beyond the slop) left uncorrected after one second.
  double collisionBias = kDefaultCollisionBias;
  bool spatialHash = false;  ///< broad phase: false the BB-tree, true a spatial hash
};

/// The option specs the backend registers, with ChipmunkSettings' defaults.
std::vector<OptionSpec> chipmunkOptionSpecs();

/// `options` must hold the specs of chipmunkOptionSpecs(); OptionSet has checked the ranges.
ChipmunkSettings readChipmunkSettings(const OptionSet& options);

}  // namespace fooball::chipmunk_detail
