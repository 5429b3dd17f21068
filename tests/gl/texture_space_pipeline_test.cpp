// Texture-space diffusion as a method of the render pipeline: a golden image per context, each
// irradiance-map optimisation against the unoptimised path, energy through the diffusion, the
// same lighting as the separable method, a separable and a texture-space object side by side,
// and one object switched between Lit, Separable and TextureSpace at run time.
#include <cmath>

#include "gl_test_support.h"
#include "image_compare.h"
#include "separable_scene.h"
#include "test_scene.h"

namespace tissue::test {
namespace {

constexpr int kSize = 256;
constexpr int kMapSize = 512;

// One Gaussian far below a texel (sigma 0.01 mm): the diffusion leaves the irradiance as it is.
render::TextureSpaceSettings identity() {
  render::TextureSpaceSettings s = skinTextureSpace(kMapSize, false);
  s.gaussians = {{1e-4f, {1.0f, 1.0f, 1.0f}}};
  return s;
}

double meanRed(const render::FloatImage& image, int x0, int x1, int y0, int y1) {
  double sum = 0.0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      sum += double(image.at(x, y).x);
  return sum / ((x1 - x0) * (y1 - y0));
}

struct Textured {
  render::MeshHandle mesh;
  render::TextureHandle base, normal;
};

Textured uploadSphere(render::Renderer& renderer, float radiusMm = 40.0f, Float3 offset = {}) {
  SphereMesh sphere = makeSphere(radiusMm, 48, 96);
  for (Float3& p : sphere.positions)
    p = {p.x + offset.x, p.y + offset.y, p.z + offset.z};
  auto mesh = renderer.createMesh(sphere.arrays());
  auto base = renderer.createTexture(makeBaseColor(256));
  auto normal = renderer.createTexture(makeBumpyNormalMap(256));
  EXPECT_TRUE(mesh && base && normal);
  return {mesh ? *mesh : render::MeshHandle{}, base ? *base : render::TextureHandle{},
          normal ? *normal : render::TextureHandle{}};
}

render::SceneObject objectOf(const Textured& t, render::MethodSettings method, const render::Material& m) {
  render::SceneObject o;
  o.mesh = t.mesh;
  o.baseColor = t.base;
  o.normalMap = t.normal;
  o.material = m;
  o.method = std::move(method);
  return o;
}

class TextureSpacePipelineTest : public ::testing::TestWithParam<Backend> {};

TEST_P(TextureSpacePipelineTest, SphereMatchesGoldenAndOptimisationsStayClose) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  const Textured sphere = uploadSphere(*renderer);
  render::Scene scene = goldenScene();
  scene.objects = {objectOf(sphere, skinTextureSpace(kMapSize, false), scene.material)};
  auto plain = renderer->renderImage(scene, kSize, kSize);
  ASSERT_TRUE(plain) << plain.error().message;
  for (const char* pass : {"texture-space:irradiance", "texture-space:blur", "texture-space:final",
                           "texture-space:copy", "composite"})
    EXPECT_NE(renderer->lastTimings().find(pass), nullptr) << pass;
  const std::string failure =
      checkGolden(std::string("texture_space_pipeline_sphere_") + backendName(GetParam()), *plain);
  EXPECT_TRUE(failure.empty()) << failure;
  // Each optimisation alone and all three against the unoptimised image: mean difference under
  // 1 level and under 1% of pixels off by more than 8 levels (the culled border and the smaller
  // map move the diffusion a little at silhouettes).
  for (int which = 0; which < 4; ++which) {
    render::TextureSpaceSettings s = skinTextureSpace(kMapSize, false);
    s.cull = which == 0 || which == 3;
    s.clip = which == 1 || which == 3;
    s.depthSize = which == 2 || which == 3;
    scene.objects[0].method = s;
    auto image = renderer->renderImage(scene, kSize, kSize);
    ASSERT_TRUE(image) << image.error().message;
    const ImageDiff d = compareImages(*image, *plain, 8);
    EXPECT_LT(d.meanDiff, 1.0) << "optimisation " << which;
    EXPECT_LT(d.fractionOver, 0.01) << "optimisation " << which;
  }
}

TEST_P(TextureSpacePipelineTest, UniformlyLitPatchKeepsItsMeanDiffuseBrightness) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  const SphereMesh patch = makePatch(200.0f, 8, 0.0f);  // fills the view
  auto mesh = renderer->createMesh(patch.arrays());
  auto stripes = renderer->createTexture(makeBaseColor(256));
  ASSERT_TRUE(mesh && stripes);
  render::Scene scene = frontScene();
  render::SceneObject o;
  o.mesh = *mesh;
  o.baseColor = *stripes;
  // The undiffused diffuse (pre-scatter albedo x irradiance), then the skin profile.
  double means[2] = {};
  for (int i = 0; i < 2; ++i) {
    o.method = i == 0 ? identity() : skinTextureSpace(kMapSize, false);
    scene.objects = {o};
    ASSERT_TRUE(renderer->renderImage(scene, kSize, kSize));
    auto diffuse = renderer->readFrame(render::FrameView::BlurredDiffuse);
    ASSERT_TRUE(diffuse);
    means[i] = meanRed(*diffuse, 40, 216, 40, 216);  // whole stripe periods, away from the border
  }
  ASSERT_GT(means[0], 0.1);
  EXPECT_NEAR(means[1] / means[0], 1.0, 0.01);  // the profile's weights sum to 1 per channel
}

TEST_P(TextureSpacePipelineTest, LightsTheSurfaceAsTheSeparableMethodDoes) {
  // Two lights, one with a shadow map, normal map and base colour: with a diffusion that does
  // nothing, texture space holds what the separable geometry pass writes before its blur.
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  const Textured sphere = uploadSphere(*renderer);
  render::Scene scene = goldenScene();
  scene.lights.push_back(scene.lights[0]);
  scene.lights[1].type = render::LightType::Directional;
  scene.lights[1].intensity = 1.0f;
  scene.lights[1].castsShadows = true;
  render::FloatImage views[2];
  for (int i = 0; i < 2; ++i) {
    scene.objects = {objectOf(sphere,
                              i == 0
                                  ? render::MethodSettings{render::rankOneSeparable(gaussianTaps(2.0f, 17))}
                                  : render::MethodSettings{identity()},
                              scene.material)};
    ASSERT_TRUE(renderer->renderImage(scene, kSize, kSize));
    auto diffuse = renderer->readFrame(render::FrameView::Diffuse);
    ASSERT_TRUE(diffuse);
    views[i] = std::move(*diffuse);
  }
  double sum = 0.0, diff = 0.0;
  int pixels = 0;
  for (int y = 1; y < kSize - 1; ++y)
    for (int x = 1; x < kSize - 1; ++x) {
      bool inside = true;  // both methods cover the pixel and its neighbours (no silhouette)
      for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i)
          inside = inside && views[0].at(x + i, y + j).w == 1.0f && views[1].at(x + i, y + j).w == 1.0f;
      if (!inside) continue;
      const Float4 a = views[0].at(x, y), b = views[1].at(x, y);
      sum += double(a.x + a.y + a.z);
      diff += std::abs(double(a.x - b.x)) + std::abs(double(a.y - b.y)) + std::abs(double(a.z - b.z));
      ++pixels;
    }
  ASSERT_GT(pixels, 10000);
  EXPECT_LT(diff / sum, 0.02);  // texture resampling of the albedo and normal map only
}

TEST_P(TextureSpacePipelineTest, SeparableAndTextureSpaceObjectsSideBySide) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  const Textured left = uploadSphere(*renderer, 30.0f, {-35.0f, 0.0f, 0.0f});
  const Textured right = uploadSphere(*renderer, 30.0f, {35.0f, 0.0f, 0.0f});
  render::Scene scene = goldenScene();
  scene.objects = {objectOf(left, render::rankOneSeparable(gaussianTaps(2.0f, 17)), scene.material),
                   objectOf(right, skinTextureSpace(kMapSize, true), scene.material)};
  auto both = renderer->renderImage(scene, kSize, kSize);
  ASSERT_TRUE(both) << both.error().message;
  auto diffuse = renderer->readFrame(render::FrameView::Diffuse);
  auto blurred = renderer->readFrame(render::FrameView::BlurredDiffuse);
  ASSERT_TRUE(diffuse && blurred);
  // The separable blur leaves the texture-space object (id 2) as it is and blurs id 1.
  double tsdChange = 0.0, sepChange = 0.0;
  int ids[3] = {};
  for (std::size_t i = 0; i < diffuse->pixels.size(); ++i) {
    const Float4 a = diffuse->pixels[i], b = blurred->pixels[i];
    const int id = int(a.w + 0.5f);
    ASSERT_TRUE(id >= 0 && id <= 2);
    ++ids[id];
    (id == 2 ? tsdChange : sepChange) += std::abs(double(a.x - b.x));
  }
  EXPECT_GT(ids[1], 2000);
  EXPECT_GT(ids[2], 2000);
  EXPECT_EQ(tsdChange, 0.0);
  EXPECT_GT(sepChange, 1.0);
  // Each object alone (the other hidden) looks as it does in the shared frame.
  for (int hidden = 0; hidden < 2; ++hidden) {
    render::Scene alone = scene;
    alone.objects[std::size_t(hidden)].visible = false;
    auto image = renderer->renderImage(alone, kSize, kSize);
    ASSERT_TRUE(image) << image.error().message;
    double d = 0.0;
    int n = 0;
    const int x0 = hidden == 0 ? kSize / 2 + 4 : 0, x1 = hidden == 0 ? kSize : kSize / 2 - 4;
    for (int y = 0; y < kSize; ++y)
      for (int x = x0; x < x1; ++x, ++n)
        for (int c = 0; c < 3; ++c)
          d += std::abs(int(image->at(x, y)[c]) - int(both->at(x, y)[c]));
    EXPECT_LT(d / (3.0 * n), 0.05) << "object " << (1 - hidden) << " alone";
  }
}

TEST_P(TextureSpacePipelineTest, OneObjectSwitchesMethodAtRunTime) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  const std::vector<render::MethodSettings> methods = {render::LitSettings{},
                                                       render::rankOneSeparable(gaussianTaps(2.0f, 17)),
                                                       skinTextureSpace(kMapSize, true)};
  const char* passes[] = {"lit", "separable:blur-y", "texture-space:final"};
  render::Scene scene = goldenScene();
  // Each method's image from a renderer that only ever drew that method.
  std::vector<Image8> expected;
  for (const auto& method : methods) {
    auto fresh = render::Renderer::create(context->procAddressFunction());
    ASSERT_TRUE(fresh) << fresh.error().message;
    scene.objects = {objectOf(uploadSphere(*fresh), method, scene.material)};
    auto image = fresh->renderImage(scene, kSize, kSize);
    ASSERT_TRUE(image) << image.error().message;
    expected.push_back(std::move(*image));
  }
  EXPECT_GT(meanDifference(expected[0], expected[2]), 0.25);  // the methods do differ
  EXPECT_GT(meanDifference(expected[1], expected[2]), 0.25);
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  scene.objects = {objectOf(uploadSphere(*renderer), methods[0], scene.material)};
  for (int m : {0, 1, 2, 0, 2, 1, 2}) {
    scene.objects[0].method = methods[std::size_t(m)];
    auto image = renderer->renderImage(scene, kSize, kSize);
    ASSERT_TRUE(image) << image.error().message;
    EXPECT_LT(meanDifference(*image, expected[std::size_t(m)]), 0.01) << "method " << m;
    EXPECT_NE(renderer->lastTimings().find(passes[m]), nullptr) << passes[m];
  }
}

TEST_P(TextureSpacePipelineTest, BadSettingsAreErrors) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  const Textured sphere = uploadSphere(*renderer, 20.0f);
  render::Scene scene = goldenScene();
  render::TextureSpaceSettings s;  // no profile
  scene.objects = {objectOf(sphere, s, scene.material)};
  auto image = renderer->renderImage(scene, 64, 64);
  ASSERT_FALSE(image);
  EXPECT_NE(image.error().message.find("Gaussians"), std::string::npos) << image.error().message;
  s = skinTextureSpace(kMapSize, true);
  std::swap(s.gaussians[0], s.gaussians[1]);  // decreasing variances
  scene.objects[0].method = s;
  EXPECT_FALSE(renderer->renderImage(scene, 64, 64));
}

INSTANTIATE_TEST_SUITE_P(Backends, TextureSpacePipelineTest, ::testing::Values(Backend::Egl, Backend::OsMesa),
                         backendParamName);

}  // namespace
}  // namespace tissue::test
