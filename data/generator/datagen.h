#pragma once
/// \file
/// The data generator's entry points (used by the `tissue-datagen` tool and by the tests that
/// check the committed data is reproduced byte for byte).

#include <filesystem>

#include "tissue/core/result.h"

namespace tissue::datagen {

/// Writes `<outDir>/meshes/{patch,liver,tube}.obj`.
Result<void> writeMeshes(const std::filesystem::path& outDir);

/// Writes `<outDir>/textures/<mesh>/{subsurface,base_color,normal_map,opacity,inner_base}.png` at
/// `size` x `size` texels for every mesh, on `threads` threads (the output does not depend on it).
Result<void> writeTextures(const std::filesystem::path& outDir, int size, int threads);

}  // namespace tissue::datagen
