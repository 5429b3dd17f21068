#pragma once
/// \file
/// Outputs are written atomically: into a temporary file beside the target, flushed, then
/// renamed over it, so a crash or a full disk never leaves a half-written file in place of a
/// good one.

#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>

#include "tissue/core/result.h"

namespace tissue {

/// Writes `bytes` to `path` atomically; creates missing parent folders.
Result<void> writeFileAtomic(const std::filesystem::path& path, std::span<const std::uint8_t> bytes);

/// Writes `text` to `path` atomically; creates missing parent folders.
Result<void> writeTextFileAtomic(const std::filesystem::path& path, std::string_view text);

/// Reads a whole file; the error names the path.
Result<std::string> readTextFile(const std::filesystem::path& path);

}  // namespace tissue
