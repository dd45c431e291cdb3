// boreas: handing the allocator's free pages back to the system after a large transient.
#pragma once

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace boreas::impl {

// glibc keeps freed memory in its arenas, one per thread that allocated, and returns only
// what lies at an arena's top; a batch add that grew its models on every core frees
// gigabytes of them (the whole models, once packed, and the blocks' staging) scattered
// through those arenas, which stayed resident: 0.3 GB after 1,000 distinct aspens.
// Elsewhere a no-op.
inline void trim_heap() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

}  // namespace boreas::impl
