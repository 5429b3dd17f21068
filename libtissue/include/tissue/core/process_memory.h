#pragma once
/// \file
/// The process's resident memory, for soak runs (issue 14, item 5): growth after warm-up is a leak.

#include <cstdint>
#include <optional>

namespace tissue {

/// Resident set size of this process, kB (Linux: /proc/self/statm's second field times the page
/// size); none where the system does not say.
std::optional<std::int64_t> residentSetKb();

/// Bytes the C heap holds in allocations now, kB (glibc's mallinfo2 uordblks + hblkhd: every
/// malloc of the process, the GL driver's included, not the pages the allocator keeps free nor
/// JIT code); none without glibc. Flat heap under a growing RSS points at fragmentation or the
/// driver's mappings rather than a leak.
std::optional<std::int64_t> heapInUseKb();

/// Hands the C heap's free pages back to the system (glibc's malloc_trim(0); nothing elsewhere),
/// so that a resident-set sample taken next counts what is held, not the allocator's high-water
/// mark after a transient peak. For soak and benchmark harnesses, never on a host's frame path.
void releaseFreeHeap();

}  // namespace tissue
