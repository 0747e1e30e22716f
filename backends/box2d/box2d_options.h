#pragma once

#include <vector>

#include "fooball/options.h"

namespace fooball::box2d_detail {

/// The Box2D backend's options as the step loop uses them: read once when an option changes,
/// never per step.
struct Box2dSettings {
  int substeps = 4;            ///< Box2D steps per step(), before auto_substeps raises it
  int velocityIterations = 8;  ///< sequential-impulse passes per Box2D step
  int positionIterations = 3;  ///< Baumgarte position-correction passes per Box2D step
  bool bullets = false;        ///< continuous collision between balls, not only against walls
  bool autoSubsteps = true;    ///< raise the substeps of a step so no ball hits b2_maxTranslation
};

/// The option specs the backend registers, with Box2dSettings' defaults.
std::vector<OptionSpec> box2dOptionSpecs();

/// `options` must hold the specs of box2dOptionSpecs(); OptionSet has checked the ranges.
Box2dSettings readBox2dSettings(const OptionSet& options);

}  // namespace fooball::box2d_detail
