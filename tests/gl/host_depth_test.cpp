// HostDepth::TestAndWrite (issue 12, embedding): a host draws an instrument in front of part of
// the organ, the renderer draws the organ into the host's framebuffer testing against and
// writing into the host's depth, then the host draws a floor behind the organ with GL_LESS.
// Every pixel is checked against an analytic ray cast of the three shapes: the instrument
// where it is in front, the tissue where it is visible, the floor only where nothing is in
// front of it, the host's background outside the viewport.
#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <string>

#include "embedding_scene.h"
#include "gl_test_support.h"
#include "tissue/gl/gl_api.h"

namespace tissue::test {
namespace {

// The host framebuffer is larger than the renderer's viewport, which is offset in it.
constexpr int kHostWidth = 160, kHostHeight = 140;
constexpr int kX = 16, kY = 8, kSize = 112;
constexpr float kRadius = 40.0f;       // mm, the organ: a sphere at the origin
constexpr float kInstrumentZ = 50.0f;  // mm, a plane in front of the sphere, x in [-200, -6]
constexpr float kInstrumentX = -6.0f;  // mm, its right edge
constexpr float kFloorZ = -25.0f;      // mm, a plane behind every visible point of the sphere
const Float4 kBackground{0.0f, 0.0f, 1.0f, 1.0f}, kInstrument{0.0f, 1.0f, 0.0f, 1.0f},
    kFloor{1.0f, 1.0f, 0.0f, 1.0f};

enum class Hit { None, Instrument, Tissue, Floor };

render::Scene organScene() {
  render::Scene scene = goldenScene();
  scene.background = {0.5f, 0.5f, 0.5f};  // never written with TestAndWrite
  return scene;
}

// What the ray through host pixel coordinates (px, py) (bottom-up, continuous) hits first.
Hit castRay(const glm::mat4& inverseViewProjection, float px, float py) {
  const float nx = (px - float(kX)) / float(kSize) * 2.0f - 1.0f,
              ny = (py - float(kY)) / float(kSize) * 2.0f - 1.0f;
  const glm::vec4 a = inverseViewProjection * glm::vec4(nx, ny, -1.0f, 1.0f);
  const glm::vec4 b = inverseViewProjection * glm::vec4(nx, ny, 1.0f, 1.0f);
  const glm::vec3 o = glm::vec3(a) / a.w, d = glm::normalize(glm::vec3(b) / b.w - o);
  float best = 1e30f;
  Hit hit = Hit::None;
  // The sphere: |o + t d| = R.
  const float bq = glm::dot(o, d), c = glm::dot(o, o) - kRadius * kRadius, disc = bq * bq - c;
  if (disc >= 0.0f) {
    const float t = -bq - std::sqrt(disc);
    if (t > 0.0f && t < best) best = t, hit = Hit::Tissue;
  }
  // The planes z = const, with their extents.
  const auto plane = [&](float z, Hit what, float xMax) {
    if (std::abs(d.z) < 1e-6f) return;
    const float t = (z - o.z) / d.z;
    const glm::vec3 p = o + t * d;
    if (t > 0.0f && t < best && p.x <= xMax && std::abs(p.x) < 400.0f && std::abs(p.y) < 400.0f)
      best = t, hit = what;
  };
  plane(kInstrumentZ, Hit::Instrument, kInstrumentX);
  plane(kFloorZ, Hit::Floor, 400.0f);
  return hit;
}

int channelDistance(const std::uint8_t* p, const Float4& c) {
  int worst = 0;
  for (int k = 0; k < 3; ++k)
    worst = std::max(worst, std::abs(int(p[k]) - int(std::lround((&c.x)[k] * 255.0f))));
  return worst;
}

struct Case {
  render::ShadingMethod method;
  int samples;
  GLenum depthFormat;  // the host's depth texture
};

std::string caseName(const ::testing::TestParamInfo<Case>& info) {
  std::string name(render::shadingMethodName(info.param.method));
  for (char& c : name)
    if (c == '-') c = '_';
  name += info.param.samples > 1 ? "_msaa" : "_single";
  name += info.param.depthFormat == GL_DEPTH_COMPONENT24  ? "_d24"
          : info.param.depthFormat == GL_DEPTH24_STENCIL8 ? "_d24s8"
                                                          : "_d32f";
  return name;
}

class HostDepthTest : public ::testing::TestWithParam<Case> {};

TEST_P(HostDepthTest, InstrumentHidesTissueAndTissueHidesTheFloor) {
  const Case k = GetParam();
  auto contextResult = createContext(Backend::Egl);
  ASSERT_TRUE(contextResult) << "no EGL context: " << contextResult.error().message;
  auto& context = *contextResult;
  auto loaded = gl::loadGl(context->procAddressFunction());
  ASSERT_TRUE(loaded) << loaded.error().message;
  const gl::GlApi& g = **loaded;
  // Step 1: the host's framebuffer, colour and depth textures.
  GLuint fbo = 0, color = 0, depth = 0;
  g.GenFramebuffers(1, &fbo);
  g.GenTextures(1, &color);
  g.GenTextures(1, &depth);
  g.BindTexture(GL_TEXTURE_2D, color);
  g.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kHostWidth, kHostHeight, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  g.BindTexture(GL_TEXTURE_2D, depth);
  const bool stencil = k.depthFormat == GL_DEPTH24_STENCIL8;
  const bool floatDepth = k.depthFormat == GL_DEPTH_COMPONENT32F;
  g.TexImage2D(GL_TEXTURE_2D, 0, GLint(k.depthFormat), kHostWidth, kHostHeight, 0,
               stencil ? GL_DEPTH_STENCIL : GL_DEPTH_COMPONENT,
               stencil ? GL_UNSIGNED_INT_24_8 : (floatDepth ? GL_FLOAT : GL_UNSIGNED_INT), nullptr);
  g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  g.BindFramebuffer(GL_FRAMEBUFFER, fbo);
  g.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color, 0);
  g.FramebufferTexture2D(GL_FRAMEBUFFER, stencil ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT,
                         GL_TEXTURE_2D, depth, 0);
  ASSERT_EQ(g.CheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));

  render::RendererSettings settings;
  settings.samples = k.samples;
  auto renderer = render::Renderer::create(context->procAddressFunction(), settings);
  ASSERT_TRUE(renderer) << renderer.error().message;
  const PlanarSphere sphere = makePlanarSphere(kRadius, 48, 96);
  auto mesh = renderer->createMesh(sphere.arrays());
  auto textures = uploadMethodTextures(*renderer);
  ASSERT_TRUE(mesh && textures);
  render::Scene scene = organScene();
  scene.objects = {methodObject(k.method, *mesh, *textures, 1.0f / (2.0f * 3.14159265f * kRadius))};
  HostDrawer host(g);
  ASSERT_TRUE(host.ok());
  const Mat4 vp = hostViewProjection(scene.camera, 1.0f);

  // Step 2: the host clears and draws the instrument (depth test on, GL_LESS), in the same
  // viewport and projection as the renderer's camera.
  g.BindFramebuffer(GL_FRAMEBUFFER, fbo);
  g.Viewport(0, 0, kHostWidth, kHostHeight);
  g.ClearColor(kBackground.x, kBackground.y, kBackground.z, 1.0f);
  g.ClearDepth(1.0);
  g.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  g.Viewport(kX, kY, kSize, kSize);
  g.Enable(GL_DEPTH_TEST);
  g.DepthFunc(GL_LESS);
  const float z = kInstrumentZ, x1 = kInstrumentX;
  host.quad(vp,
            {Float3{-400.0f, -400.0f, z}, Float3{x1, -400.0f, z}, Float3{x1, 400.0f, z},
             Float3{-400.0f, 400.0f, z}},
            kInstrument);
  // Step 3: the tissue, tested against and written into the host's depth.
  auto drawn = renderer->renderTo(scene, {.framebuffer = fbo,
                                          .x = kX,
                                          .y = kY,
                                          .width = kSize,
                                          .height = kSize,
                                          .clear = true,
                                          .depth = render::HostDepth::TestAndWrite});
  ASSERT_TRUE(drawn) << drawn.error().message;
  EXPECT_NE(renderer->lastTimings().find("host-depth"), nullptr);
  // Step 4: the floor behind the organ, still with the host's depth test (restored by renderTo).
  EXPECT_TRUE(g.IsEnabled(GL_DEPTH_TEST));
  const float f = kFloorZ;
  host.quad(vp,
            {Float3{-400.0f, -400.0f, f}, Float3{400.0f, -400.0f, f}, Float3{400.0f, 400.0f, f},
             Float3{-400.0f, 400.0f, f}},
            kFloor);
  ASSERT_TRUE(gl::checkGlError(g, "host frame"));

  // Step 5: the reference: the same scene into the same viewport without instrument or depth.
  Image8 pixels(kHostWidth, kHostHeight, 4), reference(kHostWidth, kHostHeight, 4);
  g.BindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
  g.PixelStorei(GL_PACK_ALIGNMENT, 4);
  g.ReadPixels(0, 0, kHostWidth, kHostHeight, GL_RGBA, GL_UNSIGNED_BYTE, pixels.pixels.data());
  ASSERT_TRUE(
      renderer->renderTo(scene, {.framebuffer = fbo, .x = kX, .y = kY, .width = kSize, .height = kSize}));
  g.BindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
  g.ReadPixels(0, 0, kHostWidth, kHostHeight, GL_RGBA, GL_UNSIGNED_BYTE, reference.pixels.data());

  // Step 6: pixel by pixel against the ray cast; pixels whose corners disagree are edges, skipped.
  const glm::mat4 inverse = glm::inverse(glm::make_mat4(vp.data()));
  std::vector<Hit> kind(std::size_t(kSize) * kSize);
  std::vector<bool> edge(kind.size());
  for (int j = 0; j < kSize; ++j) {
    for (int i = 0; i < kSize; ++i) {
      const float px = float(kX + i), py = float(kY + j);
      const Hit centre = castRay(inverse, px + 0.5f, py + 0.5f);
      bool e = false;
      for (const auto& [dx, dy] : {std::pair{-0.6f, -0.6f}, {1.6f, -0.6f}, {-0.6f, 1.6f}, {1.6f, 1.6f}})
        e = e || castRay(inverse, px + dx, py + dy) != centre;
      kind[std::size_t(j) * kSize + i] = centre;
      edge[std::size_t(j) * kSize + i] = e;
    }
  }
  // Tissue pixels this far from the instrument must look as without it (the separable blur and
  // the MSAA resolve reach a few pixels across the instrument's edge).
  constexpr int kMargin = 10;
  const auto nearInstrument = [&](int i, int j) {
    for (int b = std::max(j - kMargin, 0); b <= std::min(j + kMargin, kSize - 1); ++b)
      for (int a = std::max(i - kMargin, 0); a <= std::min(i + kMargin, kSize - 1); ++a)
        if (kind[std::size_t(b) * kSize + a] == Hit::Instrument) return true;
    return false;
  };
  int counts[4] = {0, 0, 0, 0}, wrong[4] = {0, 0, 0, 0}, outsideWrong = 0, compared = 0, differing = 0;
  std::string firstWrong;
  for (int py = 0; py < kHostHeight; ++py) {
    for (int px = 0; px < kHostWidth; ++px) {
      const std::size_t at = (std::size_t(py) * kHostWidth + px) * 4;  // GL rows, bottom-up
      const std::uint8_t* p = pixels.pixels.data() + at;
      const int i = px - kX, j = py - kY;
      if (i < 0 || j < 0 || i >= kSize || j >= kSize) {
        outsideWrong += channelDistance(p, kBackground) > 0;
        continue;
      }
      if (edge[std::size_t(j) * kSize + i]) continue;
      const Hit hit = kind[std::size_t(j) * kSize + i];
      ++counts[int(hit)];
      bool ok = false;
      switch (hit) {
        case Hit::None:
          ok = channelDistance(p, kBackground) == 0;
          break;
        case Hit::Instrument:
          ok = channelDistance(p, kInstrument) == 0;
          break;
        case Hit::Floor:
          ok = channelDistance(p, kFloor) == 0;
          break;
        case Hit::Tissue:  // none of the host's colours
          ok = channelDistance(p, kBackground) > 60 && channelDistance(p, kInstrument) > 60 &&
               channelDistance(p, kFloor) > 60;
          if (ok && !nearInstrument(i, j)) {
            ++compared;
            const std::uint8_t* r = reference.pixels.data() + at;
            differing += std::max({std::abs(p[0] - r[0]), std::abs(p[1] - r[1]), std::abs(p[2] - r[2])}) > 2;
          }
          break;
      }
      if (!ok) {
        ++wrong[int(hit)];
        if (firstWrong.empty()) {
          firstWrong = "pixel (" + std::to_string(px) + ", " + std::to_string(py) + ") expected kind " +
                       std::to_string(int(hit)) + ", got " + std::to_string(p[0]) + " " +
                       std::to_string(p[1]) + " " + std::to_string(p[2]);
        }
      }
    }
  }
  // The shapes all take part (the instrument hides a good share of the sphere).
  EXPECT_GT(counts[int(Hit::Instrument)], 1500);
  EXPECT_GT(counts[int(Hit::Tissue)], 2500);
  EXPECT_GT(counts[int(Hit::Floor)], 800);
  EXPECT_GT(compared, 1000);
  EXPECT_EQ(outsideWrong, 0) << "pixels outside the viewport changed";
  for (int i = 0; i < 4; ++i)
    EXPECT_EQ(wrong[i], 0) << "kind " << i << " (0 none, 1 instrument, 2 tissue, 3 floor) of " << counts[i]
                           << "; first: " << firstWrong;
  EXPECT_EQ(differing, 0) << "of " << compared
                          << " tissue pixels away from the instrument differ from the image "
                          << "drawn without it by more than 2 levels";
  g.DeleteFramebuffers(1, &fbo);
  g.DeleteTextures(1, &color);
  g.DeleteTextures(1, &depth);
}

// Ignore (the default) keeps today's behaviour: the tissue is drawn over the instrument, and
// the host's depth is left as the host wrote it (the floor then shows through the tissue).
TEST(HostDepthIgnoreTest, IgnoreDrawsOverTheInstrumentAndLeavesTheDepth) {
  auto contextResult = createContext(Backend::Egl);
  ASSERT_TRUE(contextResult) << "no EGL context: " << contextResult.error().message;
  auto& context = *contextResult;
  auto loaded = gl::loadGl(context->procAddressFunction());
  ASSERT_TRUE(loaded);
  const gl::GlApi& g = **loaded;
  GLuint fbo = 0, rb[2] = {0, 0};
  g.GenFramebuffers(1, &fbo);
  g.GenRenderbuffers(2, rb);
  g.BindRenderbuffer(GL_RENDERBUFFER, rb[0]);
  g.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, kSize, kSize);
  g.BindRenderbuffer(GL_RENDERBUFFER, rb[1]);
  g.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, kSize, kSize);
  g.BindFramebuffer(GL_FRAMEBUFFER, fbo);
  g.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
  g.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer);
  auto mesh = renderer->createMesh(makeSphere(kRadius, 24, 48).arrays());
  ASSERT_TRUE(mesh);
  render::Scene scene = organScene();
  render::SceneObject o;
  o.mesh = *mesh;
  scene.objects = {o};
  HostDrawer host(g);
  ASSERT_TRUE(host.ok());
  const Mat4 vp = hostViewProjection(scene.camera, 1.0f);
  g.Viewport(0, 0, kSize, kSize);
  g.ClearColor(0.0f, 0.0f, 1.0f, 1.0f);
  g.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  g.Enable(GL_DEPTH_TEST);
  // An instrument over the whole view, in front of the sphere.
  const float z = kInstrumentZ;
  host.quad(vp,
            {Float3{-400.0f, -400.0f, z}, Float3{400.0f, -400.0f, z}, Float3{400.0f, 400.0f, z},
             Float3{-400.0f, 400.0f, z}},
            kInstrument);
  ASSERT_TRUE(renderer->renderTo(
      scene, {.framebuffer = fbo, .x = 0, .y = 0, .width = kSize, .height = kSize, .clear = false}));
  EXPECT_EQ(renderer->lastTimings().find("host-depth"), nullptr);
  // A quad between the instrument and the sphere passes the host's depth test only if the
  // renderer left the instrument's depth alone.
  host.quad(vp,
            {Float3{-400.0f, -400.0f, 45.0f}, Float3{400.0f, -400.0f, 45.0f}, Float3{400.0f, 400.0f, 45.0f},
             Float3{-400.0f, 400.0f, 45.0f}},
            kFloor);
  Image8 pixels(kSize, kSize, 4);
  g.BindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
  g.ReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, pixels.pixels.data());
  const std::uint8_t* centre = pixels.pixels.data() + (std::size_t(kSize / 2) * kSize + kSize / 2) * 4;
  const std::uint8_t* corner = pixels.pixels.data() + (std::size_t(2) * kSize + 2) * 4;
  EXPECT_GT(channelDistance(centre, kInstrument), 60) << "the tissue is drawn over the instrument";
  EXPECT_EQ(channelDistance(corner, kInstrument), 0)
      << "uncovered pixels keep the instrument (clear = false)";
  // The quad at z = 45 lies behind the instrument: hidden everywhere, tissue or not.
  EXPECT_GT(channelDistance(centre, kFloor), 60);
  EXPECT_GT(channelDistance(corner, kFloor), 60);
  g.DeleteFramebuffers(1, &fbo);
  g.DeleteRenderbuffers(2, rb);
}

TEST(HostDepthErrorTest, ANonDepthHostFramebufferIsAnError) {
  auto contextResult = createContext(Backend::Egl);
  ASSERT_TRUE(contextResult) << "no EGL context: " << contextResult.error().message;
  auto& context = *contextResult;
  auto loaded = gl::loadGl(context->procAddressFunction());
  ASSERT_TRUE(loaded);
  const gl::GlApi& g = **loaded;
  GLuint fbo = 0, rb = 0;
  g.GenFramebuffers(1, &fbo);
  g.GenRenderbuffers(1, &rb);
  g.BindRenderbuffer(GL_RENDERBUFFER, rb);
  g.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 64, 64);
  g.BindFramebuffer(GL_FRAMEBUFFER, fbo);
  g.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer);
  ASSERT_TRUE(renderer->setMesh(makeSphere(kRadius, 12, 24).arrays()));
  auto r = renderer->renderTo(organScene(), {.framebuffer = fbo,
                                             .x = 0,
                                             .y = 0,
                                             .width = 64,
                                             .height = 64,
                                             .clear = true,
                                             .depth = render::HostDepth::TestAndWrite});
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("no depth buffer"), std::string::npos) << r.error().message;
  EXPECT_TRUE(gl::checkGlError(g, "after the refused frame"));
  g.DeleteFramebuffers(1, &fbo);
  g.DeleteRenderbuffers(1, &rb);
}

using render::ShadingMethod;
INSTANTIATE_TEST_SUITE_P(Methods, HostDepthTest,
                         ::testing::Values(Case{ShadingMethod::Lit, 0, GL_DEPTH_COMPONENT24},
                                           Case{ShadingMethod::Lit, 4, GL_DEPTH24_STENCIL8},
                                           Case{ShadingMethod::Lit, 0, GL_DEPTH_COMPONENT32F},
                                           Case{ShadingMethod::Separable, 0, GL_DEPTH_COMPONENT24},
                                           Case{ShadingMethod::Separable, 4, GL_DEPTH_COMPONENT24},
                                           Case{ShadingMethod::TextureSpace, 0, GL_DEPTH24_STENCIL8},
                                           Case{ShadingMethod::TextureSpace, 4, GL_DEPTH_COMPONENT24},
                                           Case{ShadingMethod::RayMarch, 0, GL_DEPTH_COMPONENT24},
                                           Case{ShadingMethod::Parallax, 4, GL_DEPTH_COMPONENT24}),
                         caseName);

}  // namespace
}  // namespace tissue::test
