#include "contact_slop.h"

#include <algorithm>

namespace fooball::chipmunk_detail {

void setContactCorrection(cpSpace* space, std::span<const double> radii, double slopFraction,
                          double collisionBias) {
  const double smallest = radii.empty() ? 0.0 : *std::min_element(radii.begin(), radii.end());
  cpSpaceSetCollisionSlop(space, slopFraction * smallest);
  cpSpaceSetCollisionBias(space, collisionBias);
}

}  // namespace fooball::chipmunk_detail
