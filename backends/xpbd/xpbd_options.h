#pragma once

#include <vector>

#include "fooball/options.h"

namespace fooball::xpbd {

/// The XPBD backend's options as the world uses them: read once when an option changes, never
/// per step.
struct XpbdSettings {
  /// Substeps per step, measured on the gas preset (docs/performance.md, "Speed against
  /// accuracy"): 8 leave no overlap at the end of a step (2e-14 r, against 0.009 r at 4), halve
  /// the trajectory error of 4 and put the gas's tunnelling speed at 96 m/s, twenty times its
  /// fastest ball; 16 would halve the energy loss again at twice the cost.
  int substeps = 8;
  /// Sweeps per substep: one (Müller's single velocity pass) loses a tenth of the gas's energy in
  /// 20 s at any substep count, four lose 0.17% (the passes then meet the restitution targets of
  /// contacts that share a ball), for 20–40% more cost per step.
  int iterations = 4;
};

/// The option specs the backend registers, with XpbdSettings' defaults.
std::vector<OptionSpec> xpbdOptionSpecs();

/// `options` must hold the specs of xpbdOptionSpecs(); OptionSet has checked the ranges.
XpbdSettings readXpbdSettings(const OptionSet& options);

}  // namespace fooball::xpbd
