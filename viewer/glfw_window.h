#pragma once
/// \file
/// The viewer's window: the library's GLFW window (tissue::context::openGlfwWindow, the one GLFW
/// adapter) and the user's input gathered once per frame. GLFW's header stays inside
/// glfw_window.cpp (and the panel's ImGui back end).

#include <memory>
#include <string>

#include "tissue/context/glfw_context.h"
#include "tissue/core/image.h"
#include "tissue/core/result.h"
#include "tissue/gl/proc_address.h"

namespace tissue::viewer {

/// What the user did since the last poll.
struct InputFrame {
  double cursorX = 0.0;      ///< pixels from the window's left edge (window coordinates)
  double cursorY = 0.0;      ///< pixels from the window's top edge
  double dragX = 0.0;        ///< pixels the cursor moved while the left button was held
  double dragY = 0.0;        ///< pixels, down positive
  double scrollSteps = 0.0;  ///< scroll wheel steps, positive away from the user (zoom)
  double depthSteps =
      0.0;  ///< tool depth steps, positive deeper: W, PageDown, scroll with Shift or the right button
  bool rightPressed = false;     ///< the right button went down
  bool rightReleased = false;    ///< the right button went up
  bool rightHeld = false;        ///< the right button is down now
  bool quit = false;             ///< Esc or the window's close button
  bool resetView = false;        ///< C: the home view
  bool toggleRecord = false;     ///< R: start or stop (and save) the recording
  bool toggleGrasp = false;      ///< G: grasp or release
  bool toggleNormalMap = false;  ///< N
  bool cycleMethod = false;      ///< M: the next shading method
  bool inspect = false;          ///< I: the VTK inspection of the current frame
};

/// A window with a current GL 3.3 core context. Not copyable or movable (GLFW keeps a pointer).
class Window {
 public:
  /// Opens a `width` x `height` window (screen coordinates) and makes its context current.
  /// Fails without a display, or when the driver has no GL 3.3 core context.
  static Result<std::unique_ptr<Window>> open(int width, int height, const std::string& title);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  /// Processes pending events and returns the input since the last call.
  InputFrame poll();
  /// Shows the frame drawn into the default framebuffer.
  void present();
  /// Makes the window's context current again (after another window, e.g. VTK's, took it).
  void makeCurrent();
  void setTitle(const std::string& title);

  /// Size of the default framebuffer, pixels (differs from the window size on HiDPI screens).
  void framebufferSize(int& width, int& height) const;
  /// Size of the window in the cursor's coordinates.
  void windowSize(int& width, int& height) const;
  /// Looks up GL entry points of this window's context.
  gl::GetProcAddressFn procAddress() const;
  /// The GLFW window (for the panel's ImGui back end).
  GLFWwindow* handle() const { return m_window; }
  /// The default framebuffer's back buffer as drawn so far this frame (before present()),
  /// top row first, RGBA. A read-back stall: for screenshots only, never on the frame path.
  Result<Image8> readBackBuffer() const;

 private:
  explicit Window(std::unique_ptr<context::GlfwWindow> context);
  static void onMouseButton(GLFWwindow* window, int button, int action, int mods);
  static void onScroll(GLFWwindow* window, double dx, double dy);
  static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);

  std::unique_ptr<context::GlfwWindow> m_context;  ///< the window and its context (the library's adapter)
  GLFWwindow* m_window;
  InputFrame m_pending;  ///< events collected by the callbacks since the last poll
  bool m_leftHeld = false;
  double m_lastX = 0.0, m_lastY = 0.0;
};

}  // namespace tissue::viewer
