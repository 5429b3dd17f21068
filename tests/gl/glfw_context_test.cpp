// The GLFW backend (run under xvfb-run, label "window"): a hidden window's core context.
#include <gtest/gtest.h>

#include "tissue/context/glfw_context.h"

namespace tissue::test {
namespace {

TEST(GlfwContextTest, CreatesHiddenWindowWithCoreContext) {
  context::ContextRequest request;
  request.width = 64;
  request.height = 64;
  auto context = context::createGlfwContext(request);
  if (!context) GTEST_FAIL() << "glfw context unavailable: " << context.error().message;
  const auto& info = (*context)->info();
  EXPECT_EQ(info.backend, "glfw");
  EXPECT_FALSE(info.renderer.empty());
  EXPECT_TRUE(info.major > 3 || (info.major == 3 && info.minor >= 3)) << info.version;
  EXPECT_TRUE((*context)->makeCurrent());
  (*context)->present();
}

TEST(GlfwContextTest, TwoWindowsAtOnce) {
  auto a = context::createGlfwContext();
  if (!a) GTEST_FAIL() << "glfw context unavailable: " << a.error().message;
  auto b = context::createGlfwContext();
  ASSERT_TRUE(b) << b.error().message;
  EXPECT_TRUE((*a)->makeCurrent());
  EXPECT_TRUE((*b)->makeCurrent());
}

}  // namespace
}  // namespace tissue::test
