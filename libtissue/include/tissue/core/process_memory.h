#pragma once
/// \file
/// The process's resident memory, for soak runs (issue 14, item 5): growth after warm-up is a leak.

#include <cstdint>
#include <optional>

namespace tissue {

/// Resident set size of this process, kB (Linux: /proc/self/statm's second field times the page
/// size); none where the system does not say.
std::optional<std::int64_t> residentSetKb();

}  // namespace tissue
