// The resident set size (process_memory.h).
#include "tissue/core/process_memory.h"

#include <unistd.h>

#include <fstream>

namespace tissue {

std::optional<std::int64_t> residentSetKb() {
  std::ifstream statm("/proc/self/statm");
  std::int64_t sizePages = 0, residentPages = 0;
  if (!(statm >> sizePages >> residentPages)) return std::nullopt;
  const long page = sysconf(_SC_PAGESIZE);
  if (page <= 0) return std::nullopt;
  return residentPages * std::int64_t(page) / 1024;
}

}  // namespace tissue
