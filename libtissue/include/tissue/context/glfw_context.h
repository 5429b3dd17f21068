#pragma once
/// \file
/// A GLFW window's context (target tissue_context_glfw), hidden unless `request.visible`.
/// Needs a display (X11 DISPLAY or Wayland); without one creation fails with an Error.

#include <memory>
#include <string>

#include "tissue/context/gl_context.h"

struct GLFWwindow;  // GLFW's own type, opaque here: the header stays GLFW-free

namespace tissue::context {

/// A GLFW window with its GL core context: the project's one GLFW adapter. Apps (the viewer)
/// attach their input callbacks and UI (ImGui's GLFW back end) to window(); the window, the
/// context and GLFW's process-wide initialisation live and die here.
class GlfwWindow : public GlContext {
 public:
  /// The GLFW window (valid for this object's lifetime).
  virtual GLFWwindow* window() const = 0;
};

/// Opens a `request.width` x `request.height` window titled `title` with a GL core context of
/// at least the requested version and makes it current; shown when `request.visible`.
Result<std::unique_ptr<GlfwWindow>> openGlfwWindow(const ContextRequest& request,
                                                   const std::string& title = "tissue");

/// Opens a `request.width` x `request.height` window with a GL core context and makes it current.
Result<std::unique_ptr<GlContext>> createGlfwContext(const ContextRequest& request = {});

}  // namespace tissue::context
