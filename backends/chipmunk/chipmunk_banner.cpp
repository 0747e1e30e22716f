#include "chipmunk_banner.h"

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>

namespace fooball::chipmunk_detail {

namespace {

/// Creates and frees one space with stdout sent to /dev/null, so the library's one-time banner
/// goes there. Returns true when done (the value only makes the call a static initialiser).
bool swallowBanner() {
  std::fflush(stdout);
  const int savedStdout = ::dup(STDOUT_FILENO);
  const int devNull = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
  const bool redirected =
      savedStdout >= 0 && devNull >= 0 && ::dup2(devNull, STDOUT_FILENO) == STDOUT_FILENO;
  cpSpaceFree(cpSpaceNew());
  std::fflush(stdout);
  if (redirected) ::dup2(savedStdout, STDOUT_FILENO);
  if (devNull >= 0) ::close(devNull);
  if (savedStdout >= 0) ::close(savedStdout);
  return true;
}

/// Once per process. A function-local static, so newSpaceWithoutBanner() is safe even if it runs
/// before kSwallowedAtStartup is initialised (static initialisation order across libraries).
bool bannerSwallowed() {
  static const bool done = swallowBanner();
  return done;
}

/// Runs the swallowing before main(), while the process has a single thread.
[[maybe_unused]] const bool kSwallowedAtStartup = bannerSwallowed();

}  // namespace

cpSpace* newSpaceWithoutBanner() {
  bannerSwallowed();
  return cpSpaceNew();
}

}  // namespace fooball::chipmunk_detail
