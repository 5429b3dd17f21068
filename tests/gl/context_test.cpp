// Context backends: creation, driver strings, version, backend choice, OSMesa's own entry points.
#include <cstdlib>
#include <iostream>

#include "gl_test_support.h"
#include "tissue/context/headless_context.h"
#include "tissue/gl/gl_api.h"

namespace tissue::test {
namespace {

class ContextTest : public ::testing::TestWithParam<Backend> {};

TEST_P(ContextTest, CreatesCoreContextWithInfo) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  const context::ContextInfo& info = context->info();
  EXPECT_EQ(info.backend, backendName(GetParam()));
  EXPECT_FALSE(info.vendor.empty());
  EXPECT_FALSE(info.renderer.empty());
  EXPECT_FALSE(info.version.empty());
  EXPECT_TRUE(info.major > 3 || (info.major == 3 && info.minor >= 3)) << info.version;
  ASSERT_TRUE(context->makeCurrent());
  auto gl = gl::loadGl(context->procAddressFunction());
  ASSERT_TRUE(gl) << gl.error().message;
  // A core profile has no fixed-function matrix stack: GL_PROFILE_MASK says core.
  GLint profile = 0;
  (*gl)->GetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT);
  EXPECT_TRUE(gl::checkGlError(**gl, "profile query"));
}

INSTANTIATE_TEST_SUITE_P(Backends, ContextTest, ::testing::Values(Backend::Egl, Backend::OsMesa),
                         backendParamName);

// EGL (through glvnd) and OSMesa both export gl* symbols; each context must resolve its own.
TEST(ContextTest, EglAndOsMesaLiveInOneProcessWithTheirOwnEntryPoints) {
  TISSUE_CONTEXT_OR_FAIL(egl, Backend::Egl);
  TISSUE_CONTEXT_OR_FAIL(osmesa, Backend::OsMesa);
  ASSERT_TRUE(osmesa->makeCurrent());
  EXPECT_NE(reinterpret_cast<void*>(osmesa->getProcAddress("glGetString")),
            reinterpret_cast<void*>(egl->getProcAddress("glGetString")));
  // With OSMesa current, a table loaded through OSMesaGetProcAddress must talk to OSMesa:
  // glvnd's dispatch stubs would find no current EGL context and return nothing.
  auto fromOsMesa = gl::loadGl(osmesa->procAddressFunction());
  ASSERT_TRUE(fromOsMesa) << fromOsMesa.error().message;
  EXPECT_EQ(gl::queryGlStrings(**fromOsMesa).version, osmesa->info().version);
  ASSERT_TRUE(egl->makeCurrent());
  auto fromEgl = gl::loadGl(egl->procAddressFunction());
  ASSERT_TRUE(fromEgl) << fromEgl.error().message;
  EXPECT_EQ(gl::queryGlStrings(**fromEgl).version, egl->info().version);
}

TEST(HeadlessContextTest, UnknownBackendIsAnErrorListingTheChoices) {
  auto context = context::createHeadlessContext({}, {.backend = "vulkan", .log = false});
  ASSERT_FALSE(context);
  EXPECT_NE(context.error().message.find("use egl or osmesa"), std::string::npos) << context.error().message;
}

TEST(HeadlessContextTest, TheLibraryNeverReadsTheEnvironment) {
  // A host's environment is the host's: a backend name the library would refuse is ignored.
  ::setenv("TISSUE_GL_CONTEXT", "vulkan", 1);
  ::setenv("TISSUE_EGL_PLATFORM", "nonsense", 1);
  auto context = context::createHeadlessContext({}, {.backend = "", .log = false});
  ::unsetenv("TISSUE_GL_CONTEXT");
  ::unsetenv("TISSUE_EGL_PLATFORM");
  ASSERT_TRUE(context) << "no headless context (EGL, then OSMesa): " << context.error().message;
  const std::string backend = (*context)->info().backend;
  EXPECT_TRUE(backend == "egl" || backend == "osmesa") << backend;
}

TEST(HeadlessContextTest, DefaultIsEglOrOsMesa) {
  ::unsetenv("TISSUE_GL_CONTEXT");
  auto context = context::createHeadlessContext({}, {.backend = "", .log = false});
  if (!context) GTEST_FAIL() << "no headless context: " << context.error().message;
  const std::string backend = (*context)->info().backend;
  EXPECT_TRUE(backend == "egl" || backend == "osmesa") << backend;
}

TEST(LoaderTest, FailsCleanlyWithoutAContext) {
  auto gl = gl::loadGl([](const char*) -> gl::GlProc { return nullptr; });
  ASSERT_FALSE(gl);
  EXPECT_NE(gl.error().message.find("current"), std::string::npos) << gl.error().message;
}

}  // namespace
}  // namespace tissue::test

namespace tissue::context {
namespace {

TEST(EglPlatformTest, EachPlatformCanBeAskedFor) {
  for (const std::string platform : {"device", "surfaceless"}) {
    ContextRequest request;
    request.eglPlatform = platform;
    auto context = createEglContext(request);
    if (!context) {
      std::cout << "[ SKIPPED  ] EGL " << platform << ": " << context.error().message << "\n";
      continue;
    }
    EXPECT_EQ((*context)->info().platform, platform);
    EXPECT_GE((*context)->info().major * 10 + (*context)->info().minor, 33);
  }
  ContextRequest bad;
  bad.eglPlatform = "x11";
  auto r = createEglContext(bad);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("device or surfaceless"), std::string::npos);
}

}  // namespace
}  // namespace tissue::context
