#include "translation_cap.h"

#include <algorithm>
#include <cmath>

namespace fooball::box2d_detail {

int box2dStepsBelowCap(double fastestSpeed, double gravity, double duration, int maxSteps) {
  const double reachableSpeed = fastestSpeed + gravity * duration;
  const double steps =
      std::ceil(reachableSpeed * duration / (kPlannedFractionOfCap * kMaxTranslation));
  return static_cast<int>(std::clamp(steps, 1.0, static_cast<double>(maxSteps)));
}

}  // namespace fooball::box2d_detail
