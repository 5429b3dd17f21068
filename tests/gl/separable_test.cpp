// Screen-space separable SSS (Jimenez et al. 2015; Freude 2014 ch. 4): a golden image, energy
// through the blur, follow-surface at a depth step (eq. 4.12), per-object kernels without
// bleeding, agreement with the CPU reference on a flat patch, transmittance where the shadow
// map is coarse, and the pass list.
#include <cmath>

#include "gl_test_support.h"
#include "image_compare.h"
#include "separable_scene.h"
#include "test_scene.h"
#include "tissue/reference/screen_convolution.h"

namespace tissue::test {
namespace {

constexpr int kSize = 256;

render::SeparableSettings gaussianKernel(float sigmaMm, int taps) {
  return render::rankOneSeparable(gaussianTaps(sigmaMm, taps));
}

// A texture whose left `whiteColumns` of 64 columns are white and the rest black.
Image8 halfWhite(int whiteColumns) {
  Image8 image(64, 4, 3);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 64; ++x)
      for (int c = 0; c < 3; ++c)
        image.at(x, y)[c] = x < whiteColumns ? 255 : 0;
  return image;
}

class SeparableTest : public ::testing::TestWithParam<Backend> {};

TEST_P(SeparableTest, SphereMatchesGolden) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  const GoldenSphere golden = uploadGoldenSphere(*renderer);
  ASSERT_TRUE(golden);
  render::Scene scene = goldenScene();
  render::SceneObject object = separableObject(*golden.mesh, gaussianKernel(2.0f, 17));
  object.baseColor = *golden.baseColor;
  object.normalMap = *golden.normalMap;
  object.material = scene.material;
  scene.objects = {object};
  auto image = renderer->renderImage(scene, kSize, kSize);
  ASSERT_TRUE(image) << image.error().message;
  const std::string failure = checkGolden(std::string("separable_sphere_") + backendName(GetParam()), *image);
  EXPECT_TRUE(failure.empty()) << failure;
}

TEST_P(SeparableTest, BlurKeepsTheMeanBrightnessOfAUniformlyLitPatch) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  auto scene = texturedPatchScene(*renderer, makeBaseColor(256), gaussianKernel(3.0f, 25));
  ASSERT_TRUE(scene) << scene.error().message;
  ASSERT_TRUE(renderer->renderImage(*scene, kSize, kSize));
  auto before = renderer->readFrame(render::FrameView::Diffuse);
  auto after = renderer->readFrame(render::FrameView::BlurredDiffuse);
  ASSERT_TRUE(before && after);
  // Whole stripe periods (3 per patch width) away from the image border.
  const double a = meanRedOver(*before, 40, 216, 40, 216), b = meanRedOver(*after, 40, 216, 40, 216);
  EXPECT_GT(a, 0.05);
  EXPECT_NEAR(b, a, 0.001 * a);
  // ... while the stripes themselves are blurred: a sinusoid of period P loses
  // 1 - exp(-2 pi^2 sigma^2 / P^2) = 4% of its amplitude (P = 67 mm, sigma = 3 mm).
  auto range = [](const render::FloatImage& image) {
    double lo = 1e9, hi = -1e9;
    for (int x = 40; x < 216; ++x) {
      lo = std::min(lo, static_cast<double>(image.at(x, 128).x));
      hi = std::max(hi, static_cast<double>(image.at(x, 128).x));
    }
    return hi - lo;
  };
  EXPECT_LT(range(*after), 0.98 * range(*before));
  EXPECT_GT(range(*after), 0.90 * range(*before));
}

TEST_P(SeparableTest, FollowSurfaceStopsBleedingAcrossADepthStep) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  // One object, two quads: the left (white) at z = 0, the right (black) 40 mm behind it, meeting
  // at the image's centre column. The right quad spans x 0..60 mm at z = -40 (seen from z = 200).
  SphereMesh mesh = makePatch(120.0f, 1, 0.0f);
  mesh.positions = {{-60, -60, 0}, {0, -60, 0}, {-60, 60, 0}, {0, 60, 0}};
  mesh.uvs = {{0.0f, 0.0f}, {0.49f, 0.0f}, {0.0f, 1.0f}, {0.49f, 1.0f}};
  mesh.triangles = {{0, 1, 3}, {0, 3, 2}};
  for (const Float3 p :
       {Float3{0, -72, -40}, Float3{72, -72, -40}, Float3{0, 72, -40}, Float3{72, 72, -40}}) {
    mesh.positions.push_back(p);
    mesh.normals.push_back({0, 0, 1});
    mesh.tangents.push_back({1, 0, 0, 1});
    mesh.uvs.push_back({p.x > 0 ? 1.0f : 0.51f, p.y > 0 ? 1.0f : 0.0f});
  }
  mesh.triangles.push_back({4, 5, 7});
  mesh.triangles.push_back({4, 7, 6});
  auto handle = renderer->createMesh(mesh.arrays());
  auto texture = renderer->createTexture(halfWhite(32));
  ASSERT_TRUE(handle && texture);
  render::Scene scene = frontScene();
  scene.objects = {separableObject(*handle, gaussianKernel(5.0f, 25))};
  scene.objects[0].baseColor = *texture;
  scene.objects[0].material.ambient = {};
  auto darkSide = [&](bool follow) {
    std::get<render::SeparableSettings>(scene.objects[0].method).followSurface = follow;
    EXPECT_TRUE(renderer->renderImage(scene, kSize, kSize));
    auto blurred = renderer->readFrame(render::FrameView::BlurredDiffuse);
    EXPECT_TRUE(blurred);
    return meanRedOver(*blurred, 131, 135, 120, 136);  // 3-7 px right of the step
  };
  const double without = darkSide(false), with = darkSide(true);
  EXPECT_GT(without, 0.02);  // the white side bleeds into the black one without eq. 4.12
  EXPECT_LT(with, 0.1 * without);
}

TEST_P(SeparableTest, ObjectsBlurWithTheirOwnKernelsAndDoNotBleed) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  // Two abutting patches at the same depth: left x -100..0, right 0..100.
  SphereMesh left = makePatch(100.0f, 2, 0.0f), right = makePatch(100.0f, 2, 0.0f);
  for (auto& p : left.positions)
    p.x -= 50.0f;
  for (auto& p : right.positions)
    p.x += 50.0f;
  auto a = renderer->createMesh(left.arrays());
  auto b = renderer->createMesh(right.arrays());
  auto white = renderer->createTexture(halfWhite(64));
  auto stripes = renderer->createTexture(makeBaseColor(256));
  ASSERT_TRUE(a && b && white && stripes);
  render::Scene scene = frontScene();
  scene.objects = {separableObject(*a, gaussianKernel(6.0f, 25)),
                   separableObject(*b, gaussianKernel(1.0f, 1))};
  scene.objects[0].baseColor = *white;
  scene.objects[1].baseColor = *stripes;
  ASSERT_TRUE(renderer->renderImage(scene, kSize, kSize));
  auto before = renderer->readFrame(render::FrameView::Diffuse);
  auto after = renderer->readFrame(render::FrameView::BlurredDiffuse);
  ASSERT_TRUE(before && after);
  // The right object's one-tap kernel leaves it exactly as it was, even next to the bright,
  // widely blurred left object: no bleeding in either direction.
  for (int x = 129; x < 140; ++x) {
    EXPECT_EQ(after->at(x, 128).x, before->at(x, 128).x) << "x " << x;
    EXPECT_EQ(after->at(x, 128).w, 2.0f);  // object id 2
  }
  // The left object, uniformly white up to the border, keeps its level there.
  EXPECT_NEAR(after->at(126, 128).x, before->at(126, 128).x, 0.01f * before->at(126, 128).x);
}

TEST_P(SeparableTest, BlurAgreesWithTheCpuReferenceOnAFlatPatch) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  auto scene = texturedPatchScene(*renderer, makeBaseColor(256), gaussianKernel(2.0f, 25));
  ASSERT_TRUE(scene) << scene.error().message;
  ASSERT_TRUE(renderer->renderImage(*scene, kSize, kSize));
  auto diffuse = renderer->readFrame(render::FrameView::Diffuse);
  auto position = renderer->readFrame(render::FrameView::Position);
  auto blurred = renderer->readFrame(render::FrameView::BlurredDiffuse);
  ASSERT_TRUE(diffuse && position && blurred);
  const reference::ScreenBuffers frame{kSize, kSize, diffuse->pixels, position->pixels};
  const std::vector<reference::RadialProfile> profiles{{},
                                                       reference::normalizedProfile(gaussianProfile(2.0f))};
  auto exact = reference::convolveScreen(frame, profiles);
  ASSERT_TRUE(exact) << exact.error().message;
  // Away from the image border, where the reference lacks the surface beyond the frame and the
  // blur clamps to the edge.
  double sq = 0.0, mean = 0.0;
  int n = 0;
  for (int y = 40; y < kSize - 40; ++y) {
    for (int x = 40; x < kSize - 40; ++x, ++n) {
      const double d =
          static_cast<double>(blurred->at(x, y).x) - static_cast<double>((*exact)[y * kSize + x].x);
      sq += d * d;
      mean += static_cast<double>((*exact)[y * kSize + x].x);
    }
  }
  const double rms = std::sqrt(sq / n), relative = rms / (mean / n);
  EXPECT_LT(relative, 0.01) << "rms " << rms << " of mean " << mean / n;
  // Over the whole frame the border band dominates the error.
  const auto whole = reference::compareWithReference(frame, blurred->pixels, *exact, profiles);
  EXPECT_EQ(whole.pixels, static_cast<std::size_t>(kSize * kSize));
  EXPECT_GT(whole.rms, rms);
}

// Jimenez et al. 2010's transmittance reads the light's path inside the object from the shadow
// map. On a coarse map a point on the dark side near the outline the light sees projects outside
// the texels the rasteriser covered; a single lookup there reads "nothing in front" and lit the
// dark side with T(0) (the budget bench's liver lobes showed it as streaks below every organ).
// A sphere of radius R lit along -z: the light's path to a dark-side point P is the chord 2 |P_z|,
// so wherever it is past the table's last row (10 mm) no light may come through.
TEST_P(SeparableTest, TransmittedLightStopsWhereTheChordIsThickOnACoarseShadowMap) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  render::RendererSettings coarse;
  coarse.shadowMapSize = 16;  // ~3 mm texels over the 40 mm sphere
  auto renderer = render::Renderer::create(context->procAddressFunction(), coarse);
  ASSERT_TRUE(renderer) << renderer.error().message;
  constexpr float kRadiusMm = 20.0f;
  auto mesh = renderer->createMesh(makeSphere(kRadiusMm, 48, 96).arrays());
  ASSERT_TRUE(mesh);
  render::Scene scene = frontScene();
  scene.camera.eye = {200.0f, 0.0f, 0.0f};  // from the side: both hemispheres
  scene.camera.up = {0.0f, 0.0f, 1.0f};
  scene.lights[0].castsShadows = true;
  scene.objects = {separableObject(*mesh, gaussianKernel(0.5f, 7))};
  // No ambient: the dark side's diffuse is then the transmitted light alone.
  scene.objects[0].material.ambient = {0.0f, 0.0f, 0.0f};
  auto& settings = std::get<render::SeparableSettings>(scene.objects[0].method);
  settings.transmittance = {{1, 1, 1, 0}, {0, 0, 0, 10}};
  ASSERT_TRUE(renderer->renderImage(scene, kSize, kSize));
  auto diffuse = renderer->readFrame(render::FrameView::Diffuse);
  auto position = renderer->readFrame(render::FrameView::Position);
  ASSERT_TRUE(diffuse && position);
  double litMax = 0.0, thickMax = 0.0;
  int thick = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const Float4& p = position->at(x, y);
      if (p.w <= 0.0f) continue;
      const double red = diffuse->at(x, y).x;
      if (p.z > 0.5f * kRadiusMm) litMax = std::max(litMax, red);
      if (-2.0f * p.z > 14.0f) {  // chord past 10 mm with 4 mm to spare for the map's texels
        thickMax = std::max(thickMax, red);
        ++thick;
      }
    }
  }
  ASSERT_GT(thick, 500);
  ASSERT_GT(litMax, 0.0);
  EXPECT_LT(thickMax, 0.02 * litMax) << "light through a chord past the table's 10 mm (" << thick
                                     << " pixels)";
}

TEST_P(SeparableTest, TimingsListEverySeparablePass) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  const SphereMesh sphere = makeSphere(30.0f, 16, 32), patch = makePatch(150.0f, 2, -40.0f);
  auto a = renderer->createMesh(sphere.arrays());
  auto b = renderer->createMesh(patch.arrays());
  ASSERT_TRUE(a && b);
  render::Scene scene = frontScene();
  scene.lights[0].castsShadows = true;
  render::SceneObject lit;
  lit.mesh = *b;
  scene.objects = {separableObject(*a, gaussianKernel(2.0f, 11)), lit};
  std::get<render::SeparableSettings>(scene.objects[0].method).transmittance = {{1, 1, 1, 0}, {0, 0, 0, 10}};
  ASSERT_TRUE(renderer->renderImage(scene, 128, 128));
  std::vector<std::string> names;
  std::vector<std::vector<int>> drawn;  // each pass's objects (PassTiming::issued)
  for (const auto& p : renderer->lastTimings().passes) {
    names.push_back(p.name);
    drawn.emplace_back();
    for (const auto& [object, ms] : p.issued)
      drawn.back().push_back(object);
  }
  const std::vector<std::string> expected = {
      "shadow:0",  "clear",   "lit",     "separable:geometry", "separable:blur-x", "separable:blur-y",
      "composite", "tonemap", "readback"};
  EXPECT_EQ(names, expected);
  // The geometry passes draw their objects (object 1 lit, object 0 separable); the screen-space
  // blurs draw none: they are the method's, paid once whatever its objects.
  EXPECT_EQ(drawn, (std::vector<std::vector<int>>{{}, {}, {1}, {0}, {}, {}, {}, {}, {}}));
  // A kernel that is empty, or has an empty component, is an Error naming the object.
  auto& settings = std::get<render::SeparableSettings>(scene.objects[0].method);
  settings.components.push_back({});
  auto bad = renderer->renderImage(scene, 128, 128);
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("separable object 0's kernel component 1"), std::string::npos)
      << bad.error().message;
  settings.components.clear();
  bad = renderer->renderImage(scene, 128, 128);
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("separable object 0"), std::string::npos) << bad.error().message;
}

INSTANTIATE_TEST_SUITE_P(Backends, SeparableTest, ::testing::Values(Backend::Egl, Backend::OsMesa),
                         backendParamName);

}  // namespace
}  // namespace tissue::test
