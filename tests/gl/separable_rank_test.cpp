// Rank-R separable SSS kernels (Freude 2014 eq. 5.10: K = sum_r sign_r a_r a_r^T, each
// component two 1D passes): linearity in the components with their signs, energy of an SVD
// rank-2 kernel with a negative component, SVD rank 2 against rank 1 on the CPU reference; and
// MSAA silhouettes, whose pixels must carry one real surface sample into the blur.
#include <array>
#include <cmath>

#include "gl_test_support.h"
#include "separable_scene.h"
#include "test_scene.h"
#include "tissue/gl/gl_api.h"
#include "tissue/gl/objects.h"
#include "tissue/optics/kernel.h"
#include "tissue/reference/screen_convolution.h"

namespace tissue::test {
namespace {

constexpr int kSize = 192;

// An optics kernel as the renderer's components, signs included.
render::SeparableSettings toSettings(const optics::SeparableKernel& kernel) {
  render::SeparableSettings s;
  for (const optics::KernelComponent& c : kernel.components) {
    render::SeparableComponent& out = s.components.emplace_back();
    out.sign = c.sign;
    for (const optics::KernelTap& t : c.taps)
      out.taps.push_back({t.weight.x, t.weight.y, t.weight.z, t.offsetMm});
  }
  return s;
}

std::vector<Float4> scaled(std::vector<Float4> taps, float factor) {
  for (Float4& t : taps)
    t = {t.x * factor, t.y * factor, t.z * factor, t.w};
  return taps;
}

// A checkerboard of `cells` x `cells` squares, 4 texels each.
Image8 checker(int cells) {
  Image8 image(4 * cells, 4 * cells, 3);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c)
        image.at(x, y)[c] = ((x / 4 + y / 4) % 2) ? 230 : 40;
  return image;
}

// A radial profile R(r) tabulated to `rMaxMm` for the kernel builder (double; kernel domain
// +-halfWidthMm) and for the CPU reference (float) alike.
struct Tabulated {
  optics::RadialProfileRgb optics;
  reference::RadialProfile reference;
};

template <class Profile>  // Float3 (mm^-2) of r (mm)
Tabulated tabulate(Profile profile, float rMaxMm, float halfWidthMm) {
  Tabulated p;
  p.optics.name = "test profile";
  p.optics.kernelHalfWidthMm = halfWidthMm;
  for (int i = 0; i <= 2000; ++i) {
    const float r = rMaxMm * static_cast<float>(i) / 2000.0f;
    const Float3 v = profile(r);
    p.optics.radiusMm.push_back(r);
    p.optics.value[0].push_back(v.x);
    p.optics.value[1].push_back(v.y);
    p.optics.value[2].push_back(v.z);
    p.reference.radiusMm.push_back(r);
    p.reference.value.push_back(v);
  }
  return p;
}

float gaussian2d(float r, float sigmaMm) {
  return std::exp(-r * r / (2 * sigmaMm * sigmaMm)) / (2 * 3.14159265f * sigmaMm * sigmaMm);
}

// Per channel a narrow and a wide 2D Gaussian (0.6 and 0.4 of the energy): no single separable
// component represents it, two do exactly (each Gaussian separates).
Tabulated twoGaussians() {
  return tabulate(
      [](float r) {
        auto mix = [r](float narrow, float wide) {
          return 0.6f * gaussian2d(r, narrow) + 0.4f * gaussian2d(r, wide);
        };
        return Float3{mix(1.5f, 6.0f), mix(1.2f, 4.5f), mix(1.0f, 3.5f)};
      },
      36.0f, 24.0f);
}

// A ring, R = r^2 G_sigma(r): as a matrix x^2 g(x) g(y) + g(x) y^2 g(y) = u v^T + v u^T, of rank 2
// with eigenvalues of both signs, so its SVD rank-2 kernel has a component of sign -1. (The
// dipole profiles of Jensen's materials give only positive components, ranks 2 to 8.)
Tabulated ring() {
  return tabulate(
      [](float r) {
        return Float3{r * r * gaussian2d(r, 3.0f), r * r * gaussian2d(r, 2.5f), r * r * gaussian2d(r, 2.0f)};
      },
      18.0f, 12.0f);
}

class SeparableRankTest : public ::testing::TestWithParam<Backend> {};

TEST_P(SeparableRankTest, RankRIsTheSignedSumOfItsComponentsRenderedAlone) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  // A textured patch (rank 3, mixed signs) behind a sphere (rank 1) in one frame.
  const SphereMesh patch = makePatch(200.0f, 4, -30.0f), sphere = makeSphere(35.0f, 24, 48);
  auto a = renderer->createMesh(patch.arrays());
  auto b = renderer->createMesh(sphere.arrays());
  auto texture = renderer->createTexture(checker(24));
  ASSERT_TRUE(a && b && texture);
  render::SeparableSettings rank3;
  rank3.components = {{scaled(gaussianTaps(1.5f, 11), 1.3f), {1, 1, 1}},
                      {scaled(gaussianTaps(4.0f, 17), 0.6f), {-1, 1, -1}},
                      {scaled(gaussianTaps(2.5f, 7), 0.5f), {1, -1, 1}}};
  rank3.followSurfaceMm = 8.0f;
  render::Scene scene = frontScene();
  scene.objects = {separableObject(*a, rank3),
                   separableObject(*b, render::rankOneSeparable(gaussianTaps(2, 9)))};
  scene.objects[0].baseColor = scene.objects[1].baseColor = *texture;
  auto blurred = [&](const render::SeparableSettings& patchKernel) {
    scene.objects[0].method = patchKernel;
    EXPECT_TRUE(renderer->renderImage(scene, kSize, kSize));
    auto image = renderer->readFrame(render::FrameView::BlurredDiffuse);
    EXPECT_TRUE(image);
    return image ? *image : render::FloatImage{};
  };
  const render::FloatImage whole = blurred(rank3);
  std::vector<render::FloatImage> alone;
  for (const render::SeparableComponent& c : rank3.components) {
    render::SeparableSettings one = rank3;
    one.components = {c};
    alone.push_back(blurred(one));
  }
  ASSERT_EQ(whole.pixels.size(), static_cast<std::size_t>(kSize * kSize));
  double worst = 0.0, change = 0.0;
  int patchPixels = 0;
  for (std::size_t i = 0; i < whole.pixels.size(); ++i) {
    const Float4 w = whole.pixels[i];
    if (w.w == 2.0f) {  // the rank-1 sphere: untouched by the patch's other components
      EXPECT_EQ(w, alone[0].pixels[i]) << "pixel " << i;
      continue;
    }
    if (w.w != 1.0f) continue;
    ++patchPixels;
    const Float4 s0 = alone[0].pixels[i], s1 = alone[1].pixels[i], s2 = alone[2].pixels[i];
    const Float3 sum{s0.x + s1.x + s2.x, s0.y + s1.y + s2.y, s0.z + s1.z + s2.z};
    // Half-float targets round each pass to 11 bits: allow ~4 units in the last place of the
    // terms' magnitude (a wrong sign or a lost component is off by a whole term).
    const double scale = std::abs(double(s0.x)) + std::abs(double(s1.x)) + std::abs(double(s2.x)) +
                         std::abs(double(s0.y)) + std::abs(double(s1.y)) + std::abs(double(s2.y)) +
                         std::abs(double(s0.z)) + std::abs(double(s1.z)) + std::abs(double(s2.z));
    const double d =
        std::abs(double(w.x - sum.x)) + std::abs(double(w.y - sum.y)) + std::abs(double(w.z - sum.z));
    worst = std::max(worst, d / std::max(scale, 1e-3));
    change = std::max(change, std::abs(double(w.x - s0.x)));
  }
  EXPECT_GT(patchPixels, kSize * kSize / 2);
  EXPECT_GT(change, 0.05);  // the other components matter (so the sum is a real check)
  EXPECT_LT(worst, 2e-3);   // relative to the terms' magnitudes
  // The pass list: a pair per component of the frame's highest rank. The blended passes leave
  // the host's blend function and equation as they were.
  auto loaded = gl::loadGl(context->procAddressFunction());
  ASSERT_TRUE(loaded);
  const gl::GlApi& g = **loaded;
  g.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_DST_COLOR, GL_ZERO);
  g.BlendEquation(GL_FUNC_REVERSE_SUBTRACT);
  std::vector<std::string> names;
  scene.objects[0].method = rank3;
  ASSERT_TRUE(renderer->renderImage(scene, kSize, kSize));
  GLint blend[5] = {};
  for (int i = 0; i < 5; ++i)
    g.GetIntegerv(std::array{GL_BLEND_SRC_RGB, GL_BLEND_DST_RGB, GL_BLEND_SRC_ALPHA, GL_BLEND_DST_ALPHA,
                             GL_BLEND_EQUATION_RGB}[static_cast<std::size_t>(i)],
                  &blend[i]);
  EXPECT_EQ(blend[0], GL_SRC_ALPHA);
  EXPECT_EQ(blend[1], GL_ONE_MINUS_SRC_ALPHA);
  EXPECT_EQ(blend[2], GL_DST_COLOR);
  EXPECT_EQ(blend[3], GL_ZERO);
  EXPECT_EQ(blend[4], GL_FUNC_REVERSE_SUBTRACT);
  g.BlendFunc(GL_ONE, GL_ZERO);
  g.BlendEquation(GL_FUNC_ADD);
  for (const auto& p : renderer->lastTimings().passes)
    if (p.name.rfind("separable:blur", 0) == 0) names.push_back(p.name);
  EXPECT_EQ(names,
            (std::vector<std::string>{"separable:blur-x", "separable:blur-y", "separable:blur-x:1",
                                      "separable:blur-y:1", "separable:blur-x:2", "separable:blur-y:2"}));
}

TEST_P(SeparableRankTest, SvdRank2KeepsTheMeanOfAFlatPatchWithANegativeComponent) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  optics::KernelSettings ks;
  ks.taps = 17;
  ks.rank = 2;
  ks.normalizeEnergy = true;  // Freude eq. 5.12
  auto kernel = optics::buildKernel(ring().optics, optics::KernelModel::Svd, ks);
  ASSERT_TRUE(kernel) << kernel.error().message;
  ASSERT_EQ(kernel->components.size(), 2u);
  const Float3 sign = kernel->components[1].sign;
  ASSERT_TRUE(sign.x < 0 || sign.y < 0 || sign.z < 0) << "no negative component to test";
  const auto energy = optics::kernelEnergy(*kernel);
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  auto scene = texturedPatchScene(*renderer, makeBaseColor(256), toSettings(*kernel));
  ASSERT_TRUE(scene) << scene.error().message;
  ASSERT_TRUE(renderer->renderImage(*scene, 256, 256));
  auto before = renderer->readFrame(render::FrameView::Diffuse);
  auto after = renderer->readFrame(render::FrameView::BlurredDiffuse);
  ASSERT_TRUE(before && after);
  for (int c = 0; c < 3; ++c) {
    // Whole stripe periods away from the border; the mean scales by the kernel's total
    // sum_r sign_r (sum of a_r)^2, which eq. 5.12 makes 1.
    const double a = meanOver(*before, 40, 216, 40, 216, c), b = meanOver(*after, 40, 216, 40, 216, c);
    EXPECT_NEAR(energy[static_cast<std::size_t>(c)], 1.0, 0.01) << "channel " << c;
    EXPECT_NEAR(b, a * energy[static_cast<std::size_t>(c)], 0.002 * a) << "channel " << c;
    EXPECT_NEAR(b, a, 0.01 * a) << "channel " << c;
  }
}

TEST_P(SeparableRankTest, SvdRank2IsCloserToTheReferenceThanRank1) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  const Tabulated profile = twoGaussians();
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  auto scene = texturedPatchScene(*renderer, checker(40), {});
  ASSERT_TRUE(scene) << scene.error().message;
  const std::vector<reference::RadialProfile> profiles{{}, reference::normalizedProfile(profile.reference)};
  std::vector<Float4> diffuse, position;
  std::vector<Float3> exact;
  auto rms = [&](int rank) {
    optics::KernelSettings ks;
    ks.taps = 25;
    ks.rank = rank;
    auto kernel = optics::buildKernel(profile.optics, optics::KernelModel::Svd, ks);
    EXPECT_TRUE(kernel) << kernel.error().message;
    scene->objects[0].method = toSettings(*kernel);
    EXPECT_TRUE(renderer->renderImage(*scene, kSize, kSize));
    if (exact.empty()) {  // the pre-blur frame is the same for every kernel
      diffuse = renderer->readFrame(render::FrameView::Diffuse)->pixels;
      position = renderer->readFrame(render::FrameView::Position)->pixels;
      exact = *reference::convolveScreen({kSize, kSize, diffuse, position}, profiles);
    }
    auto blurred = renderer->readFrame(render::FrameView::BlurredDiffuse);
    return reference::compareWithReference({kSize, kSize, diffuse, position}, blurred->pixels, exact,
                                           profiles)
        .rms;
  };
  const double rank1 = rms(1), rank2 = rms(2);
  EXPECT_LT(rank2, 0.8 * rank1) << "rank 1 " << rank1 << ", rank 2 " << rank2;
}

// A white patch turned 20 degrees about the view axis, smaller than the frame: its silhouette
// pixels are partly covered. MSAA 4.
TEST_P(SeparableRankTest, MsaaSilhouettePixelsCarryARealSurfaceSampleAndNoBackground) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto renderer = render::Renderer::create(context->procAddressFunction(),
                                           {.shaders = {}, .samples = 4, .gpuTimers = false});
  ASSERT_TRUE(renderer) << renderer.error().message;
  SphereMesh patch = makePatch(100.0f, 2, 0.0f);
  const float c = std::cos(0.35f), s = std::sin(0.35f);
  for (Float3& p : patch.positions)
    p = {c * p.x - s * p.y, s * p.x + c * p.y, p.z};
  auto mesh = renderer->createMesh(patch.arrays());
  ASSERT_TRUE(mesh);
  render::Scene scene = frontScene();
  render::SeparableSettings kernel = render::rankOneSeparable(gaussianTaps(4.0f, 25));
  kernel.followSurface = false;  // depth alone would hide a wrong id or colour at the edge
  scene.objects = {separableObject(*mesh, kernel)};
  // A multisample texture the host has bound on the unit the resolve uses stays bound.
  auto loaded = gl::loadGl(context->procAddressFunction());
  ASSERT_TRUE(loaded);
  const gl::GlApi& g = **loaded;
  gl::Texture host = gl::Texture::create(g);
  g.ActiveTexture(GL_TEXTURE3);
  g.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, host.id());
  g.TexImage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, 4, GL_RGBA8, 4, 4, GL_TRUE);
  ASSERT_TRUE(renderer->renderImage(scene, kSize, kSize));
  GLint bound = 0;
  g.ActiveTexture(GL_TEXTURE3);
  g.GetIntegerv(GL_TEXTURE_BINDING_2D_MULTISAMPLE, &bound);
  EXPECT_EQ(static_cast<GLuint>(bound), host.id());
  g.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
  g.ActiveTexture(GL_TEXTURE0);
  auto radiance = renderer->readFrame(render::FrameView::Radiance);
  auto diffuse = renderer->readFrame(render::FrameView::Diffuse);
  auto position = renderer->readFrame(render::FrameView::Position);
  auto blurred = renderer->readFrame(render::FrameView::BlurredDiffuse);
  ASSERT_TRUE(radiance && diffuse && position && blurred);
  const float level = diffuse->at(kSize / 2, kSize / 2).x;  // the uniformly lit surface
  ASSERT_GT(level, 0.1f);
  int edges = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const float coverage = radiance->at(x, y).w;
      if (coverage <= 0.0f) continue;
      if (coverage < 1.0f) {
        ++edges;
        // One real sample: the patch's id, its depth (200 mm: the plane z = 0 seen from z = 200)
        // and its own colour, undarkened by the background.
        EXPECT_EQ(diffuse->at(x, y).w, 1.0f) << x << ", " << y;
        EXPECT_NEAR(position->at(x, y).w, 200.0f, 0.01f) << x << ", " << y;
        EXPECT_NEAR(diffuse->at(x, y).x, level, 0.01f * level) << x << ", " << y;
        // The blurred edge is the surface's level weighted by its coverage (as the tone map expects).
        EXPECT_NEAR(blurred->at(x, y).x, coverage * level, 0.01f * level) << x << ", " << y;
      } else {
        // Fully covered pixels next to the edge: no background darkens them through the blur.
        EXPECT_NEAR(blurred->at(x, y).x, level, 0.01f * level) << x << ", " << y;
      }
    }
  }
  EXPECT_GT(edges, 100);
}

INSTANTIATE_TEST_SUITE_P(Backends, SeparableRankTest, ::testing::Values(Backend::Egl, Backend::OsMesa),
                         backendParamName);

}  // namespace
}  // namespace tissue::test
