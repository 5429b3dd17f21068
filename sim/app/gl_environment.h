#pragma once
/// \file
/// tissue-sim's GL settings from the environment. The library never reads environment variables
/// (a host's process is the host's); the apps read them here and pass them in:
///   TISSUE_GL_CONTEXT    egl | osmesa: the headless backend (empty: EGL, then OSMesa)
///   TISSUE_EGL_PLATFORM  device | surfaceless: the EGL platform (empty: device, then surfaceless)
///   TISSUE_SHADER_DIR    a folder whose GLSL files override the embedded ones (live editing)

#include <memory>
#include <string>

#include "tissue/context/gl_context.h"
#include "tissue/context/headless_context.h"
#include "tissue/core/result.h"
#include "tissue/gl/shader_library.h"
#include "tissue/render/renderer.h"

namespace tissue::sim_app {

/// A headless context as the environment asks (see above), made current; `log`: one stderr line
/// naming the context (and one per fallback).
Result<std::unique_ptr<context::GlContext>> createAppContext(context::ContextRequest request = {},
                                                             bool log = true);

/// A renderer on `context` (current) with the environment's shaders, `samples` MSAA (0: off) and
/// GPU timer queries when `gpuTimers`.
Result<render::Renderer> createAppRenderer(const context::GlContext& context, int samples, bool gpuTimers);

/// The shader sources' override folder from TISSUE_SHADER_DIR (empty: embedded only).
gl::ShaderLibrarySettings shaderSettingsFromEnvironment();
/// TISSUE_GL_CONTEXT (empty: EGL, then OSMesa), for context::HeadlessOptions::backend.
std::string glContextFromEnvironment();
/// TISSUE_EGL_PLATFORM (empty: device, then surfaceless), for context::ContextRequest::eglPlatform.
std::string eglPlatformFromEnvironment();

}  // namespace tissue::sim_app
