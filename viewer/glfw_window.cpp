// The viewer's GLFW window and its input callbacks.
#include "glfw_window.h"

#include <GLFW/glfw3.h>

#include <algorithm>

namespace tissue::viewer {
namespace {

Window& windowOf(GLFWwindow* window) {
  return *static_cast<Window*>(glfwGetWindowUserPointer(window));
}

}  // namespace

Result<std::unique_ptr<Window>> Window::open(int width, int height, const std::string& title) {
  // The window, its context and GLFW's initialisation: the library's one GLFW adapter.
  context::ContextRequest request;
  request.width = width;
  request.height = height;
  request.visible = true;
  auto window = context::openGlfwWindow(request, title);
  if (!window) return window.error();
  glfwSwapInterval(1);
  std::unique_ptr<Window> result(new Window(std::move(*window)));
  GLFWwindow* w = result->m_window;
  glfwSetWindowUserPointer(w, result.get());
  glfwSetMouseButtonCallback(w, &Window::onMouseButton);
  glfwSetScrollCallback(w, &Window::onScroll);
  glfwSetKeyCallback(w, &Window::onKey);
  return result;
}

Window::Window(std::unique_ptr<context::GlfwWindow> context)
    : m_context(std::move(context)), m_window(m_context->window()) {
  glfwGetCursorPos(m_window, &m_lastX, &m_lastY);
}

Window::~Window() {
  // The adapter destroys the window (and GLFW with its last window); the callbacks go first.
  glfwSetWindowUserPointer(m_window, nullptr);
  glfwSetMouseButtonCallback(m_window, nullptr);
  glfwSetScrollCallback(m_window, nullptr);
  glfwSetKeyCallback(m_window, nullptr);
}

InputFrame Window::poll() {
  glfwPollEvents();
  InputFrame input = m_pending;
  m_pending = {};
  glfwGetCursorPos(m_window, &input.cursorX, &input.cursorY);
  if (m_leftHeld) {
    input.dragX = input.cursorX - m_lastX;
    input.dragY = input.cursorY - m_lastY;
  }
  m_lastX = input.cursorX;
  m_lastY = input.cursorY;
  input.rightHeld = glfwGetMouseButton(m_window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
  input.quit = input.quit || glfwWindowShouldClose(m_window);
  return input;
}

void Window::present() {
  m_context->present();
}

void Window::makeCurrent() {
  (void)m_context->makeCurrent();
}

void Window::setTitle(const std::string& title) {
  glfwSetWindowTitle(m_window, title.c_str());
}

void Window::framebufferSize(int& width, int& height) const {
  glfwGetFramebufferSize(m_window, &width, &height);
}

void Window::windowSize(int& width, int& height) const {
  glfwGetWindowSize(m_window, &width, &height);
}

gl::GetProcAddressFn Window::procAddress() const {
  return m_context->procAddressFunction();
}

Result<Image8> Window::readBackBuffer() const {
  // GL 1.0 entry points, looked up like the renderer's (GLFW_INCLUDE_NONE: no GL header here).
  using PixelStorei = void (*)(unsigned, int);
  using ReadBuffer = void (*)(unsigned);
  using ReadPixels = void (*)(int, int, int, int, unsigned, unsigned, void*);
  const auto pixelStorei = reinterpret_cast<PixelStorei>(glfwGetProcAddress("glPixelStorei"));
  const auto readBuffer = reinterpret_cast<ReadBuffer>(glfwGetProcAddress("glReadBuffer"));
  const auto readPixels = reinterpret_cast<ReadPixels>(glfwGetProcAddress("glReadPixels"));
  if (!pixelStorei || !readBuffer || !readPixels)
    return Error{"screenshot: no glReadPixels in this GL context"};
  int width = 0, height = 0;
  framebufferSize(width, height);
  if (width <= 0 || height <= 0) return Error{"screenshot: the window is minimised"};
  constexpr unsigned kPackAlignment = 0x0D05, kBack = 0x0405, kRgba = 0x1908, kUnsignedByte = 0x1401;
  Image8 bottomUp(width, height, 4);
  pixelStorei(kPackAlignment, 1);
  readBuffer(kBack);
  readPixels(0, 0, width, height, kRgba, kUnsignedByte, bottomUp.at(0, 0));
  Image8 image(width, height, 4);
  for (int y = 0; y < height; ++y) {
    std::copy_n(bottomUp.at(0, height - 1 - y), std::size_t(width) * 4, image.at(0, y));
    for (int x = 0; x < width; ++x)
      image.at(x, y)[3] = 255;  // the panel's blending leaves alpha below 1; a screenshot is opaque
  }
  return image;
}

void Window::onMouseButton(GLFWwindow* window, int button, int action, int /*mods*/) {
  Window& self = windowOf(window);
  if (button == GLFW_MOUSE_BUTTON_LEFT) self.m_leftHeld = action == GLFW_PRESS;
  if (button == GLFW_MOUSE_BUTTON_RIGHT && action == GLFW_PRESS) self.m_pending.rightPressed = true;
  if (button == GLFW_MOUSE_BUTTON_RIGHT && action == GLFW_RELEASE) self.m_pending.rightReleased = true;
}

void Window::onScroll(GLFWwindow* window, double /*dx*/, double dy) {
  // With Shift or while the right button pokes, the wheel moves the tool: away from the user
  // pushes deeper.
  const bool depth = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS ||
                     glfwGetKey(window, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ||
                     glfwGetKey(window, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
  (depth ? windowOf(window).m_pending.depthSteps : windowOf(window).m_pending.scrollSteps) += dy;
}

void Window::onKey(GLFWwindow* window, int key, int /*scancode*/, int action, int /*mods*/) {
  InputFrame& pending = windowOf(window).m_pending;
  // Depth keys repeat while held; the others act once per press.
  if (action != GLFW_RELEASE && (key == GLFW_KEY_W || key == GLFW_KEY_PAGE_DOWN)) pending.depthSteps += 1.0;
  if (action != GLFW_RELEASE && (key == GLFW_KEY_S || key == GLFW_KEY_PAGE_UP)) pending.depthSteps -= 1.0;
  if (action != GLFW_PRESS) return;
  if (key == GLFW_KEY_ESCAPE) pending.quit = true;
  if (key == GLFW_KEY_C) pending.resetView = true;
  if (key == GLFW_KEY_R) pending.toggleRecord = true;
  if (key == GLFW_KEY_G) pending.toggleGrasp = true;
  if (key == GLFW_KEY_N) pending.toggleNormalMap = true;
  if (key == GLFW_KEY_I) pending.inspect = true;
  if (key == GLFW_KEY_M) pending.cycleMethod = true;
}

}  // namespace tissue::viewer
