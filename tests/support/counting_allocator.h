// Counts the process's heap allocations, for tests that prove a hot path allocates nothing.
// Link counting_allocator.cpp into the test binary (and only into allocation tests: it replaces
// the allocator). Normal builds count every malloc/calloc/realloc (interposed over glibc's);
// under AddressSanitizer, which owns malloc, only operator new is counted.
#pragma once

namespace vtest {

/// Allocations made by the process so far.
long allocation_count();

}  // namespace vtest
