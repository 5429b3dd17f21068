// Headless EGL: device platform, then surfaceless; a core context with no surface.
#include "tissue/context/egl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace tissue::context {
namespace {

bool hasExtension(const char* list, const char* name) {
  if (!list) return false;
  const std::size_t n = std::strlen(name);
  for (const char* p = std::strstr(list, name); p; p = std::strstr(p + 1, name)) {
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  }
  return false;
}

std::string eglErrorText() {
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "0x%04X", static_cast<unsigned>(eglGetError()));
  return std::string("EGL error ") + buffer;
}

class EglContext final : public GlContext {
 public:
  EglContext(EGLDisplay display, EGLContext context) : m_display(display), m_context(context) {}
  // The display is not terminated: EGL displays are per process and platform device, so
  // eglTerminate would also pull the display from under any other context on it.
  ~EglContext() override {
    if (eglGetCurrentContext() == m_context)
      eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(m_display, m_context);
  }
  Result<void> makeCurrent() override {
    if (eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, m_context) != EGL_TRUE) {
      return Error{"egl: eglMakeCurrent failed, " + eglErrorText()};
    }
    return {};
  }
  gl::GlProc getProcAddress(const char* name) const override { return eglGetProcAddress(name); }
  const ContextInfo& info() const override { return m_info; }
  void setInfo(ContextInfo info) { m_info = std::move(info); }

 private:
  EGLDisplay m_display;
  EGLContext m_context;
  ContextInfo m_info;
};

// Creates a surfaceless core context on an initialised display.
Result<EGLContext> createCoreContext(EGLDisplay display, const ContextRequest& request) {
  const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
  if (!hasExtension(extensions, "EGL_KHR_surfaceless_context")) {
    return Error{"no EGL_KHR_surfaceless_context"};
  }
  if (eglBindAPI(EGL_OPENGL_API) != EGL_TRUE) return Error{"eglBindAPI(EGL_OPENGL_API) failed"};
  EGLConfig config = EGL_NO_CONFIG_KHR;
  if (!hasExtension(extensions, "EGL_KHR_no_config_context")) {
    const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_DONT_CARE,
                                    EGL_NONE};
    EGLint count = 0;
    if (eglChooseConfig(display, configAttribs, &config, 1, &count) != EGL_TRUE || count == 0) {
      return Error{"no EGL config renders OpenGL, " + eglErrorText()};
    }
  }
  const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                   request.glMajor,
                                   EGL_CONTEXT_MINOR_VERSION,
                                   request.glMinor,
                                   EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                   EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                   EGL_CONTEXT_OPENGL_DEBUG,
                                   request.debug ? EGL_TRUE : EGL_FALSE,
                                   EGL_NONE};
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttribs);
  if (context == EGL_NO_CONTEXT) return Error{"eglCreateContext (GL core) failed, " + eglErrorText()};
  if (eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context) != EGL_TRUE) {
    eglDestroyContext(display, context);
    return Error{"eglMakeCurrent without surface failed, " + eglErrorText()};
  }
  return context;
}

// Tries one display: initialise, create the context, read the strings.
Result<std::unique_ptr<GlContext>> tryDisplay(EGLDisplay display, const ContextRequest& request,
                                              const std::string& platform) {
  if (display == EGL_NO_DISPLAY) return Error{platform + ": no display"};
  EGLint major = 0, minor = 0;
  if (eglInitialize(display, &major, &minor) != EGL_TRUE) return Error{platform + ": eglInitialize failed"};
  auto context = createCoreContext(display, request);
  if (!context) return Error{platform + ": " + context.error().message};
  auto result = std::make_unique<EglContext>(display, *context);
  auto info = queryContextInfo(result->procAddressFunction(), request, "egl", platform);
  if (!info) return Error{platform + ": " + info.error().message};
  result->setInfo(std::move(*info));
  return std::unique_ptr<GlContext>(std::move(result));
}

}  // namespace

Result<std::unique_ptr<GlContext>> createEglContext(const ContextRequest& request) {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!client) return Error{"egl: no client extensions (EGL 1.5 or EGL_EXT_client_extensions needed)"};
  auto getPlatformDisplay =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!getPlatformDisplay) return Error{"egl: no eglGetPlatformDisplayEXT"};
  std::string why;
  const std::string& only = request.eglPlatform;
  if (!only.empty() && only != "device" && only != "surfaceless") {
    return Error{"egl: unknown EGL platform '" + only + "' (TISSUE_EGL_PLATFORM); use device or surfaceless"};
  }

  // Step 1: the device platform: one display per GPU (or Mesa's software device).
  if (only == "surfaceless") {
    why = "device: not tried (surfaceless asked for)";
  } else if (hasExtension(client, "EGL_EXT_platform_device")) {
    auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    EGLint count = 0;
    std::vector<EGLDeviceEXT> devices(16);
    if (queryDevices &&
        queryDevices(static_cast<EGLint>(devices.size()), devices.data(), &count) == EGL_TRUE) {
      for (EGLint i = 0; i < count; ++i) {
        EGLDisplay display =
            getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[static_cast<std::size_t>(i)], nullptr);
        auto context = tryDisplay(display, request, "device");
        if (context) return context;
        why += (why.empty() ? "" : "; ") + context.error().message + " (device " + std::to_string(i) + ")";
      }
      if (count == 0) why = "device: no EGL devices";
    } else {
      why = "device: eglQueryDevicesEXT failed";
    }
  } else {
    why = "device: no EGL_EXT_platform_device";
  }

  // Step 2: Mesa's surfaceless platform.
  if (only == "device") {
    why += "; surfaceless: not tried (device asked for)";
  } else if (hasExtension(client, "EGL_MESA_platform_surfaceless")) {
    EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    auto context = tryDisplay(display, request, "surfaceless");
    if (context) return context;
    why += "; " + context.error().message;
  } else {
    why += "; surfaceless: no EGL_MESA_platform_surfaceless";
  }
  return Error{"egl: no headless GL " + std::to_string(request.glMajor) + "." +
               std::to_string(request.glMinor) + " core context (" + why + ")"};
}

}  // namespace tissue::context
