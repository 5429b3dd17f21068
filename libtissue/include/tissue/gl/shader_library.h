#pragma once
/// \file
/// GLSL sources: the files of shaders/ are embedded in the binary at build time; for live
/// editing, a file present in the override folder is read from disk instead. Variants are
/// made by injecting `#define`s after the `#version` line, and `#include "common/x.glsl"`
/// lines are replaced by that file (each file is included at most once per shader).

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tissue/core/result.h"

namespace tissue::gl {

/// One `#define NAME VALUE` injected into a shader (VALUE may be empty).
struct ShaderDefine {
  std::string name;
  std::string value;
};

/// Where shader sources come from.
struct ShaderLibrarySettings {
  /// Folder read before the embedded copy (live editing); empty: embedded sources only. Apps pass
  /// $TISSUE_SHADER_DIR here (the library never reads the environment).
  std::filesystem::path overrideDir;
};

/// A shader after preprocessing, with the files it was assembled from.
struct PreprocessedShader {
  std::string source;              ///< ready for glShaderSource
  std::vector<std::string> files;  ///< files[i] is GLSL source-string number i in `#line` and logs
};

/// Finds and preprocesses shader sources. Cheap to copy; holds no GL state.
class ShaderLibrary {
 public:
  explicit ShaderLibrary(ShaderLibrarySettings settings = {});

  /// The raw text of `name` (a path relative to shaders/, e.g. "lit.frag").
  Result<std::string> source(std::string_view name) const;

  /// `name` with `defines` injected after `#version` and includes resolved. Errors name the
  /// file and line of a missing include, a missing `#version` or an include cycle.
  Result<PreprocessedShader> preprocess(std::string_view name,
                                        std::span<const ShaderDefine> defines = {}) const;

  /// The override folder in effect (empty when none).
  const std::filesystem::path& overrideDir() const { return m_overrideDir; }

 private:
  std::filesystem::path m_overrideDir;
};

namespace detail {
/// One embedded file (generated at build time from shaders/).
struct EmbeddedShader {
  const char* name;
  const char* source;
};
/// Every embedded shader file.
std::span<const EmbeddedShader> embeddedShaders();
}  // namespace detail

}  // namespace tissue::gl
