#pragma once
/// \file
/// A GLFW window's context (target tissue_context_glfw), hidden unless `request.visible`.
/// Needs a display (X11 DISPLAY or Wayland); without one creation fails with an Error.

#include <memory>

#include "tissue/context/gl_context.h"

namespace tissue::context {

/// Opens a `request.width` x `request.height` window with a GL core context and makes it current.
Result<std::unique_ptr<GlContext>> createGlfwContext(const ContextRequest& request = {});

}  // namespace tissue::context
