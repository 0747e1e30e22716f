#include "chipmunk_space.h"

#include <algorithm>

#include "chipmunk_banner.h"

namespace fooball::chipmunk_detail {

Space::Space() : space_(newSpaceWithoutBanner()) {}

Space::~Space() {
  cpSpaceFree(space_);
  for (cpShape* shape : shapes_)
    cpShapeFree(shape);
  for (cpBody* body : bodies_)
    cpBodyFree(body);
}

cpBody* Space::add(cpBody* body) {
  bodies_.push_back(body);
  return cpSpaceAddBody(space_, body);
}

cpShape* Space::add(cpShape* shape) {
  shapes_.push_back(shape);
  return cpSpaceAddShape(space_, shape);
}

void Space::remove(cpShape* shape) {
  cpSpaceRemoveShape(space_, shape);
  shapes_.erase(std::find(shapes_.begin(), shapes_.end(), shape));
  cpShapeFree(shape);
}

}  // namespace fooball::chipmunk_detail
