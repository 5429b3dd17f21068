#pragma once
/// \file
/// Headless EGL contexts (target tissue_context_egl): the device platform
/// (EGL_EXT_platform_device) first, then Mesa's surfaceless platform
/// (EGL_MESA_platform_surfaceless). No surface: rendering goes into framebuffer objects.

#include <memory>

#include "tissue/context/gl_context.h"

namespace tissue::context {

/// Creates a GL core context of at least `request`'s version and makes it current. The error
/// says which platforms were tried and why each failed.
Result<std::unique_ptr<GlContext>> createEglContext(const ContextRequest& request = {});

}  // namespace tissue::context
