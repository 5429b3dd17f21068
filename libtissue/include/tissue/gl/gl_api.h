#pragma once
/// \file
/// The GL function table. Every GL call of tissue goes through a glad multi-context table
/// (`GladGLContext`, generated at build time for GL 3.3 core) loaded from a caller-given
/// getProcAddress, never through the process's global gl* symbols: two contexts of different
/// backends (EGL and OSMesa, which both export gl* symbols) can live in one process.
/// This header is public within tissue_gl only; tissue_render keeps it out of its own headers.

#include <glad/gl.h>

#include <memory>
#include <string>

#include "tissue/core/result.h"
#include "tissue/gl/proc_address.h"

namespace tissue::gl {

/// A loaded GL 3.3 core function table (valid for contexts that share the loader's driver).
using GlApi = GladGLContext;

/// Loads the function table through `getProcAddress`; a context must be current. Fails when
/// the context is older than GL 3.3 or a core entry point is missing.
Result<std::shared_ptr<const GlApi>> loadGl(const GetProcAddressFn& getProcAddress);

/// GL_VENDOR, GL_RENDERER and GL_VERSION of the current context.
struct GlStrings {
  std::string vendor;
  std::string renderer;
  std::string version;
  int major = 0;  ///< context version, major
  int minor = 0;  ///< context version, minor
};

/// Reads the strings of the current context.
GlStrings queryGlStrings(const GlApi& gl);

/// The name of a glGetError code ("GL_INVALID_OPERATION"), for messages.
const char* glErrorName(unsigned int error);

/// Returns an Error naming `where` when glGetError reports one (and drains the error queue).
Result<void> checkGlError(const GlApi& gl, const char* where);

}  // namespace tissue::gl
