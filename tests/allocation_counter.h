#pragma once

namespace fooball::testing {

/// Calls to operator new so far in this test binary (linking allocation_counter.cpp replaces
/// the global operator new and delete). Compare before and after a call to prove it does not
/// allocate.
long allocationCount();

}  // namespace fooball::testing
