#pragma once
/// \file
/// Choosing a headless context backend (target tissue_contexts): HeadlessOptions::backend = egl |
/// osmesa picks one; empty, EGL is tried first and OSMesa when EGL fails (the reason is logged on
/// stderr in one line). The library never reads the environment: apps read TISSUE_GL_CONTEXT and
/// TISSUE_EGL_PLATFORM and pass them in. Headless contexts do not link GLFW (a window is the
/// viewer's or the host's, tissue_context_glfw).

#include <memory>
#include <string>

#include "tissue/context/gl_context.h"

namespace tissue::context {

/// How createHeadlessContext picks its backend.
struct HeadlessOptions {
  /// "egl", "osmesa", or empty: EGL with OSMesa fallback.
  std::string backend;
  bool log = true;  ///< one stderr line per fallback and one with vendor/renderer/version
};

/// Creates a context as described above and makes it current. Unknown backend names are an
/// Error listing the allowed values.
Result<std::unique_ptr<GlContext>> createHeadlessContext(const ContextRequest& request = {},
                                                         const HeadlessOptions& options = {});

}  // namespace tissue::context
