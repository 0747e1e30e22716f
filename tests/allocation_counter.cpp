// Replaces the global operator new/delete with counting versions. In a translation unit of its
// own, so the compiler never inlines the replacements into callers (where GCC would take the
// malloc/free pair for a mismatched new/delete).

#include "allocation_counter.h"

#include <atomic>
#include <cstdlib>
#include <new>

namespace {
std::atomic<long> allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  ++allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}

namespace fooball::testing {

long allocationCount() {
  return allocations.load();
}

}  // namespace fooball::testing
