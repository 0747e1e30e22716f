#pragma once

#include <chipmunk/chipmunk.h>

namespace fooball::chipmunk_detail {

/// cpSpaceNew, without the banner Debian's Chipmunk prints.
///
/// Debian builds libchipmunk7 (7.0.3) without NDEBUG, so cpSpaceInit prints, the first time a
/// process creates a space, two lines to stdout with printf:
///   Initializing cpSpace - Chipmunk v7.0.3 (Debug Enabled)
///   Compile with -DNDEBUG defined to disable debug mode and runtime assertion checks
/// (`strings libchipmunk.so.7.0.3`; a static flag inside the library, nothing to switch it off).
/// That would land in the middle of `fooball-cli run --metrics -` output, of CSV on stdout, and in
/// every test's log. So the first space of the process is created with file descriptor 1 pointed
/// at /dev/null: stdout is flushed before (nothing of ours is held back or lost) and after (the
/// banner, still in stdio's buffer when stdout is a pipe or file, goes to /dev/null), then fd 1 is
/// restored. This happens once, from a static initialiser of this library (chipmunk_banner.cpp),
/// before main() starts any thread that could write to stdout in those microseconds; later spaces
/// are created directly. If fd 1 cannot be duplicated (closed stdout), there is nothing to
/// protect and the space is created as is.
cpSpace* newSpaceWithoutBanner();

}  // namespace fooball::chipmunk_detail
