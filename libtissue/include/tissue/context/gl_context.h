#pragma once
/// \file
/// The platform side of rendering (Filament's "platform"): a GL context that can be made
/// current, resolves GL entry points and presents. It never changes GL state. A host that owns
/// its own context does not need this at all: the renderer only takes a getProcAddress.

#include <memory>
#include <string>

#include "tissue/core/result.h"
#include "tissue/gl/proc_address.h"

namespace tissue::context {

/// What a caller asks of a new context.
struct ContextRequest {
  int glMajor = 3;       ///< minimum GL core version, major (tissue needs 3.3)
  int glMinor = 3;       ///< minimum GL core version, minor
  int width = 64;        ///< pixels; the window (GLFW) or the default buffer (OSMesa) size
  int height = 64;       ///< pixels
  bool visible = false;  ///< GLFW only: show the window
  bool debug = false;    ///< ask for a debug context where the backend supports it
  /// EGL only: "device", "surfaceless", or empty: device then surfaceless (apps pass
  /// $TISSUE_EGL_PLATFORM here; the library never reads the environment).
  std::string eglPlatform;
};

/// Who made the context and what the driver says about itself.
struct ContextInfo {
  std::string backend;   ///< "egl", "osmesa" or "glfw"
  std::string platform;  ///< backend detail, e.g. "device" or "surfaceless" for EGL
  std::string vendor;    ///< GL_VENDOR
  std::string renderer;  ///< GL_RENDERER
  std::string version;   ///< GL_VERSION
  int major = 0;         ///< GL context version, major
  int minor = 0;         ///< GL context version, minor
};

/// A GL context of some backend. Move-free: owned through std::unique_ptr.
class GlContext {
 public:
  virtual ~GlContext() = default;
  GlContext() = default;
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  /// Makes the context current on the calling thread.
  virtual Result<void> makeCurrent() = 0;
  /// The address of GL function `name` for this context (it should be current); null when unknown.
  virtual gl::GlProc getProcAddress(const char* name) const = 0;
  /// Shows the back buffer (windowed backends); a no-op for headless ones, which render to FBOs.
  virtual void present() {}
  /// Backend and driver strings, read once at creation.
  virtual const ContextInfo& info() const = 0;

  /// getProcAddress as a function object for the renderer and loader (captures `this`).
  gl::GetProcAddressFn procAddressFunction() const {
    return [this](const char* name) { return getProcAddress(name); };
  }
};

/// Reads GL_VENDOR/RENDERER/VERSION of the context current now through `getProcAddress`
/// and checks it is at least `request`'s version. Used by the backends after creation.
Result<ContextInfo> queryContextInfo(const gl::GetProcAddressFn& getProcAddress,
                                     const ContextRequest& request, std::string backend,
                                     std::string platform);

}  // namespace tissue::context
