#pragma once
/// \file
/// Choosing a context backend (target tissue_contexts): environment variable
/// TISSUE_GL_CONTEXT = egl | osmesa | glfw picks one; unset, EGL is tried first and OSMesa
/// when EGL fails (the reason is logged on stderr in one line).

#include <memory>
#include <string>

#include "tissue/context/gl_context.h"

namespace tissue::context {

/// How createHeadlessContext picks its backend.
struct HeadlessOptions {
  /// "egl", "osmesa", "glfw", or empty: then TISSUE_GL_CONTEXT, else EGL with OSMesa fallback.
  std::string backend;
  bool log = true;  ///< one stderr line per fallback and one with vendor/renderer/version
};

/// Creates a context as described above and makes it current. Unknown backend names are an
/// Error listing the allowed values.
Result<std::unique_ptr<GlContext>> createHeadlessContext(const ContextRequest& request = {},
                                                         const HeadlessOptions& options = {});

}  // namespace tissue::context
