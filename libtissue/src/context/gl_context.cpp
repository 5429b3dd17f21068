// Reading the driver strings of a freshly created context (shared by every backend).
#include "tissue/context/gl_context.h"

#include "tissue/gl/gl_api.h"

namespace tissue::context {

Result<ContextInfo> queryContextInfo(const gl::GetProcAddressFn& getProcAddress,
                                     const ContextRequest& request, std::string backend,
                                     std::string platform) {
  auto gl = gl::loadGl(getProcAddress);
  if (!gl) return Error{backend + ": " + gl.error().message};
  const gl::GlStrings s = gl::queryGlStrings(**gl);
  if (s.major < request.glMajor || (s.major == request.glMajor && s.minor < request.glMinor)) {
    return Error{backend + ": got GL " + s.version + ", need " + std::to_string(request.glMajor) + "." +
                 std::to_string(request.glMinor) + " core"};
  }
  return ContextInfo{
      std::move(backend), std::move(platform), s.vendor, s.renderer, s.version, s.major, s.minor};
}

}  // namespace tissue::context
