// The GL function table: loading through a caller-given getProcAddress, strings, errors.
#include "tissue/gl/gl_api.h"

#include <string>

namespace tissue::gl {
namespace {

// glad's user-pointer loader: forwards to the caller's std::function.
GLADapiproc loadThrough(void* user, const char* name) {
  const auto& fn = *static_cast<const GetProcAddressFn*>(user);
  return reinterpret_cast<GLADapiproc>(fn(name));
}

std::string glString(const GlApi& gl, GLenum which) {
  const GLubyte* s = gl.GetString ? gl.GetString(which) : nullptr;
  return s ? std::string(reinterpret_cast<const char*>(s)) : std::string();
}

}  // namespace

Result<std::shared_ptr<const GlApi>> loadGl(const GetProcAddressFn& getProcAddress) {
  if (!getProcAddress) return Error{"GL loader: no getProcAddress function given"};
  auto gl = std::make_shared<GlApi>();
  // gladLoadGLContextUserPtr reads GL_VERSION itself: it returns 0 when no context is current
  // or glGetString is missing.
  const int version =
      gladLoadGLContextUserPtr(gl.get(), loadThrough, const_cast<GetProcAddressFn*>(&getProcAddress));
  if (version == 0) {
    return Error{
        "GL loader: could not load GL through getProcAddress; is a GL context current on this thread?"};
  }
  const int major = GLAD_VERSION_MAJOR(version);
  const int minor = GLAD_VERSION_MINOR(version);
  if (major < 3 || (major == 3 && minor < 3) || !gl->VERSION_3_3) {
    return Error{"GL loader: the current context is GL " + std::to_string(major) + "." +
                 std::to_string(minor) + " (" + glString(*gl, GL_VERSION) +
                 "); tissue needs a GL 3.3 core context"};
  }
  return std::shared_ptr<const GlApi>(std::move(gl));
}

GlStrings queryGlStrings(const GlApi& gl) {
  GlStrings s;
  s.vendor = glString(gl, GL_VENDOR);
  s.renderer = glString(gl, GL_RENDERER);
  s.version = glString(gl, GL_VERSION);
  if (gl.GetIntegerv) {
    gl.GetIntegerv(GL_MAJOR_VERSION, &s.major);
    gl.GetIntegerv(GL_MINOR_VERSION, &s.minor);
  }
  return s;
}

const char* glErrorName(unsigned int error) {
  switch (error) {
    case GL_NO_ERROR:
      return "GL_NO_ERROR";
    case GL_INVALID_ENUM:
      return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE:
      return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
      return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION:
      return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY:
      return "GL_OUT_OF_MEMORY";
    default:
      return "unknown GL error";
  }
}

Result<void> checkGlError(const GlApi& gl, const char* where) {
  const GLenum first = gl.GetError();
  if (first == GL_NO_ERROR) return {};
  // Drain the queue so a later check does not report this error again (bounded: a lost
  // context can report errors forever).
  for (int i = 0; i < 16 && gl.GetError() != GL_NO_ERROR; ++i) {
  }
  return Error{std::string(where) + ": " + glErrorName(first)};
}

}  // namespace tissue::gl
