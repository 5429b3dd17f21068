// A GLFW window's GL core context.
#include "tissue/context/glfw_context.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <mutex>

namespace tissue::context {
namespace {

// GLFW itself is process-wide state (glfwInit/glfwTerminate); this counts the windows of
// tissue so the last one terminates GLFW. The count is GLFW's constraint, not tissue state.
struct GlfwLibrary {
  std::mutex mutex;
  int users = 0;
};
GlfwLibrary& glfwLibrary() {
  static GlfwLibrary library;
  return library;
}

std::string lastGlfwError() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description ? description : "unknown GLFW error";
}

class GlfwContext final : public GlfwWindow {
 public:
  explicit GlfwContext(GLFWwindow* window) : m_window(window) {}
  ~GlfwContext() override {
    glfwDestroyWindow(m_window);
    auto& library = glfwLibrary();
    std::lock_guard lock(library.mutex);
    if (--library.users == 0) glfwTerminate();
  }
  Result<void> makeCurrent() override {
    glfwMakeContextCurrent(m_window);
    if (glfwGetCurrentContext() != m_window)
      return Error{"glfw: glfwMakeContextCurrent failed: " + lastGlfwError()};
    return {};
  }
  gl::GlProc getProcAddress(const char* name) const override { return glfwGetProcAddress(name); }
  void present() override { glfwSwapBuffers(m_window); }
  const ContextInfo& info() const override { return m_info; }
  GLFWwindow* window() const override { return m_window; }
  void setInfo(ContextInfo info) { m_info = std::move(info); }

 private:
  GLFWwindow* m_window;
  ContextInfo m_info;
};

}  // namespace

Result<std::unique_ptr<GlContext>> createGlfwContext(const ContextRequest& request) {
  auto window = openGlfwWindow(request);
  if (!window) return window.error();
  return std::unique_ptr<GlContext>(std::move(*window));
}

Result<std::unique_ptr<GlfwWindow>> openGlfwWindow(const ContextRequest& request, const std::string& title) {
  auto& library = glfwLibrary();
  GLFWwindow* window = nullptr;
  {
    std::lock_guard lock(library.mutex);
    if (library.users == 0 && glfwInit() != GLFW_TRUE) {
      return Error{"glfw: glfwInit failed (" + lastGlfwError() +
                   "); a window needs a display, e.g. run under Xvfb"};
    }
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, request.glMajor);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, request.glMinor);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, request.debug ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_VISIBLE, request.visible ? GLFW_TRUE : GLFW_FALSE);
    window = glfwCreateWindow(std::max(request.width, 1), std::max(request.height, 1), title.c_str(), nullptr,
                              nullptr);
    if (!window) {
      const std::string why = lastGlfwError();
      if (library.users == 0) glfwTerminate();
      return Error{"glfw: no window with a GL " + std::to_string(request.glMajor) + "." +
                   std::to_string(request.glMinor) + " core context (" + why + ")"};
    }
    ++library.users;
  }
  auto context = std::make_unique<GlfwContext>(window);
  if (auto current = context->makeCurrent(); !current) return current.error();
  auto info = queryContextInfo(context->procAddressFunction(), request, "glfw", "window");
  if (!info) return info.error();
  context->setInfo(std::move(*info));
  return std::unique_ptr<GlfwWindow>(std::move(context));
}

}  // namespace tissue::context
