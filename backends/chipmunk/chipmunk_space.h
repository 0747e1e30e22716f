#pragma once

#include <chipmunk/chipmunk.h>

#include <vector>

namespace fooball::chipmunk_detail {

/// A cpSpace and everything added to it, freed together. Chipmunk's cpSpaceFree frees neither
/// bodies nor shapes, and cpSpaceDestroy still touches the bodies (it activates each), so the
/// space goes first and its children after.
class Space {
 public:
  Space();  ///< an empty space (chipmunk_banner.h: without Debian's banner)
  ~Space();
  Space(const Space&) = delete;
  Space& operator=(const Space&) = delete;

  cpSpace* get() const { return space_; }

  /// Adds a body created with cpBodyNew and takes ownership of it.
  cpBody* add(cpBody* body);
  /// Adds a shape created with cpCircleShapeNew/cpSegmentShapeNew and takes ownership of it.
  cpShape* add(cpShape* shape);
  /// Removes a shape added with add() and frees it.
  void remove(cpShape* shape);

 private:
  cpSpace* space_;
  std::vector<cpBody*> bodies_;
  std::vector<cpShape*> shapes_;
};

}  // namespace fooball::chipmunk_detail
