// Layered parallax multi-texturing (Oat 2006; Norberg 2010 §2.2, §3.2) in the pipeline: a golden
// image per context, the inner layer seen at the eq. 15-18 offset of the CPU function, the
// lightmap blur keeping a uniform lightmap's level (energy) while smoothing a spot, the passes,
// the run-time switch Lit -> Parallax -> Lit, objects of different methods in one frame, and
// bad settings.
#include <cmath>
#include <numbers>

#include "gl_test_support.h"
#include "image_compare.h"
#include "test_scene.h"
#include "tissue/render/parallax_math.h"

namespace tissue::test {
namespace {

constexpr int kSize = 256;

// A black texture with a white vertical line at u = 0.5 (columns 127-128 of 256).
Image8 lineTexture() {
  Image8 image(256, 16, 3);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 256; ++x)
      for (int c = 0; c < 3; ++c)
        image.at(x, y)[c] = (x == 127 || x == 128) ? 255 : 0;
  return image;
}

Image8 solid(std::uint8_t v) {
  Image8 image(4, 4, 3);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x)
      for (int c = 0; c < 3; ++c)
        image.at(x, y)[c] = v;
  return image;
}

// A vessel-like inner layer: dark red with brighter branching lines (sRGB).
Image8 vesselTexture(int size) {
  Image8 image(size, size, 3);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const float u = float(x) / float(size), v = float(y) / float(size);
      const float a = std::abs(std::sin(6.2831853f * (5.0f * u + 0.7f * std::sin(6.2831853f * 2.0f * v))));
      const float b = std::abs(std::sin(6.2831853f * (3.0f * v + 0.5f * std::sin(6.2831853f * 3.0f * u))));
      const float line = std::max(a < 0.08f ? 1.0f : 0.0f, b < 0.06f ? 1.0f : 0.0f);
      image.at(x, y)[0] = std::uint8_t(120 + 100 * line);
      image.at(x, y)[1] = std::uint8_t(30 + 10 * line);
      image.at(x, y)[2] = std::uint8_t(40 + 20 * line);
    }
  return image;
}

// A camera at `angleDeg` from +z in the xz plane, 200 mm from the origin, looking at it.
render::Scene angledScene(float angleDeg) {
  render::Scene scene;
  const float a = angleDeg * std::numbers::pi_v<float> / 180.0f;
  scene.camera.eye = {200.0f * std::sin(a), 0.0f, 200.0f * std::cos(a)};
  scene.camera.verticalFovDeg = 30.0f;
  scene.camera.nearMm = 50.0f;
  scene.camera.farMm = 400.0f;
  scene.lights[0].type = render::LightType::Directional;
  scene.lights[0].direction = {0.0f, 0.0f, -1.0f};
  return scene;
}

render::ParallaxSettings oneLayer(render::TextureHandle base, float depthMm) {
  render::ParallaxSettings s;
  s.layers = {render::ParallaxLayer{base, depthMm, 1.0f}};
  return s;
}

class ParallaxTest : public ::testing::TestWithParam<Backend> {};

TEST_P(ParallaxTest, SphereMatchesGolden) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  const GoldenSphere golden = uploadGoldenSphere(*renderer);
  auto vessels = renderer->createTexture(vesselTexture(256));
  ASSERT_TRUE(golden && vessels);
  render::Scene scene = goldenScene();
  render::SceneObject object;
  object.mesh = *golden.mesh;
  object.baseColor = *golden.baseColor;
  object.normalMap = *golden.normalMap;
  object.material = scene.material;
  render::ParallaxSettings s = oneLayer(*vessels, 2.0f);
  s.opacity = 0.4f;
  s.lightmap.size = 512;
  object.method = s;
  scene.objects = {object};
  auto image = renderer->renderImage(scene, kSize, kSize);
  ASSERT_TRUE(image) << image.error().message;
  const std::string failure = checkGolden(std::string("parallax_sphere_") + backendName(GetParam()), *image);
  EXPECT_TRUE(failure.empty()) << failure;
  std::vector<std::string> names;
  for (const auto& p : renderer->lastTimings().passes)
    names.push_back(p.name);
  const std::vector<std::string> expected = {
      "clear",   "parallax:lightmap", "parallax:lightmap-blur", "parallax:geometry", "composite",
      "tonemap", "readback"};
  EXPECT_EQ(names, expected);
}

TEST_P(ParallaxTest, InnerLayerAppearsAtTheSnellOffset) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  const SphereMesh patch = makePatch(100.0f, 4, 0.0f);  // u = 0.5 at x = 0
  auto mesh = renderer->createMesh(patch.arrays());
  auto line = renderer->createTexture(lineTexture());
  ASSERT_TRUE(mesh && line);
  for (const float angle : {0.0f, 45.0f}) {
    render::Scene scene = angledScene(angle);
    render::SceneObject o;
    o.mesh = *mesh;
    render::ParallaxSettings s = oneLayer(*line, 5.0f);
    s.opacity = 0.0f;
    s.innerBlurPerMm = 0.0f;
    s.refractiveIndex = 1.4f;
    o.method = s;
    scene.objects = {o};
    ASSERT_TRUE(renderer->renderImage(scene, kSize, kSize));
    auto radiance = renderer->readFrame(render::FrameView::Radiance);
    auto position = renderer->readFrame(render::FrameView::Position);
    ASSERT_TRUE(radiance && position);
    // The brightest pixel of the centre row, and where on the surface (mm) it lies.
    int best = 0;
    for (int x = 0; x < kSize; ++x)
      if (radiance->at(x, kSize / 2).x > radiance->at(best, kSize / 2).x) best = x;
    const float seenAtMm = position->at(best, kSize / 2).x;
    // The eye is toward +x: the transmission vector leans to -x, so the line (x = 0 on the
    // inner layer) is seen at x = +d tan(theta_t).
    const float v = angle * std::numbers::pi_v<float> / 180.0f;
    const auto expected =
        render::transmissionLookup({std::sin(v), 0.0f, std::cos(v)}, {0.0f, 0.0f, 1.0f}, 1.4f, 5.0f);
    EXPECT_NEAR(seenAtMm, -expected.offsetMm.x, 0.6f) << angle << " deg";
    if (angle > 0.0f) {
      EXPECT_GT(seenAtMm, 2.0f);  // clearly shifted (2.92 mm expected)
    }
  }
}

TEST_P(ParallaxTest, LightmapBlurKeepsAUniformLevelAndSmoothsASpot) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  const SphereMesh patch = makePatch(100.0f, 8, 0.0f);
  auto mesh = renderer->createMesh(patch.arrays());
  auto white = renderer->createTexture(solid(255));
  ASSERT_TRUE(mesh && white);
  render::Scene scene = angledScene(0.0f);
  render::SceneObject o;
  o.mesh = *mesh;
  o.baseColor = *white;
  o.material.specular = 0.0f;
  o.material.ambient = {};
  auto innerRed = [&](float blurMm, const render::Scene& sc, int x0, int x1) {
    render::ParallaxSettings s = oneLayer(*white, 1.0f);
    s.opacity = 0.0f;
    s.innerBlurPerMm = 0.0f;
    s.lightmap.blurRadiusMm = blurMm;
    s.lightmap.blurPasses = blurMm > 0.0f ? 3 : 0;
    o.method = s;
    render::Scene withObject = sc;
    withObject.objects = {o};
    EXPECT_TRUE(renderer->renderImage(withObject, kSize, kSize));
    auto radiance = renderer->readFrame(render::FrameView::Radiance);
    EXPECT_TRUE(radiance);
    return meanRedOver(*radiance, x0, x1, kSize / 2 - 20, kSize / 2 + 20);
  };
  // Uniform irradiance (a directional light along -z): the blurred map has the same level.
  const double sharp = innerRed(0.0f, scene, 40, 216), blurred = innerRed(8.0f, scene, 40, 216);
  EXPECT_GT(sharp, 0.5);
  EXPECT_NEAR(blurred, sharp, 0.005 * sharp);
  // A point light 15 mm above the patch: a bright spot the blur spreads (lower peak, same mean
  // over a window much larger than the blur).
  render::Scene spot = scene;
  spot.lights[0].type = render::LightType::Point;
  spot.lights[0].positionMm = {0.0f, 0.0f, 15.0f};
  const double peakSharp = innerRed(0.0f, spot, 124, 132), peakBlurred = innerRed(8.0f, spot, 124, 132);
  EXPECT_LT(peakBlurred, 0.97 * peakSharp);
  const double meanSharp = innerRed(0.0f, spot, 8, 248), meanBlurred = innerRed(8.0f, spot, 8, 248);
  EXPECT_NEAR(meanBlurred, meanSharp, 0.03 * meanSharp);
}

TEST_P(ParallaxTest, SwitchingLitParallaxLitGivesTheLitImageBack) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  const SphereMesh sphere = makeSphere(40.0f, 32, 64);
  auto mesh = renderer->createMesh(sphere.arrays());
  auto base = renderer->createTexture(makeBaseColor(128));
  auto vessels = renderer->createTexture(vesselTexture(128));
  ASSERT_TRUE(mesh && base && vessels);
  render::Scene scene = goldenScene();
  render::SceneObject o;
  o.mesh = *mesh;
  o.baseColor = *base;
  scene.objects = {o};
  auto lit = renderer->renderImage(scene, kSize, kSize);
  scene.objects[0].method = oneLayer(*vessels, 2.0f);
  auto parallax = renderer->renderImage(scene, kSize, kSize);
  scene.objects[0].method = render::LitSettings{};
  auto litAgain = renderer->renderImage(scene, kSize, kSize);
  ASSERT_TRUE(lit && parallax && litAgain) << (parallax ? "" : parallax.error().message);
  EXPECT_EQ(compareImages(*litAgain, *lit, 0).maxDiff, 0);
  EXPECT_GT(meanDifference(*parallax, *lit), 1.0);  // the method did change the image
  EXPECT_EQ(renderer->lastTimings().find("parallax:geometry"), nullptr);
}

TEST_P(ParallaxTest, ObjectsOfDifferentMethodsShareAFrameUnchanged) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  SphereMesh left = makeSphere(25.0f, 24, 48), right = makeSphere(25.0f, 24, 48);
  for (auto& p : left.positions)
    p.x -= 30.0f;
  for (auto& p : right.positions)
    p.x += 30.0f;
  auto a = renderer->createMesh(left.arrays());
  auto b = renderer->createMesh(right.arrays());
  auto vessels = renderer->createTexture(vesselTexture(128));
  ASSERT_TRUE(a && b && vessels);
  render::Scene scene = angledScene(0.0f);
  scene.camera.verticalFovDeg = 40.0f;
  render::SceneObject litObject, parallaxObject;
  litObject.mesh = *a;
  parallaxObject.mesh = *b;
  parallaxObject.method = oneLayer(*vessels, 2.0f);
  auto render = [&](std::vector<render::SceneObject> objects) {
    scene.objects = std::move(objects);
    EXPECT_TRUE(renderer->renderImage(scene, kSize, kSize));
    auto r = renderer->readFrame(render::FrameView::Radiance);
    EXPECT_TRUE(r);
    return *r;
  };
  // Each object's pixels are what it gives alone: nothing of one method reaches the other's
  // pixels. Returns the largest red difference; `covered` counts the pixels of each half.
  auto worstAgainstAlone = [&](const render::SceneObject& l, const render::SceneObject& r) {
    const render::FloatImage both = render({l, r}), leftOnly = render({l}), rightOnly = render({r});
    double worst = 0.0;
    int covered[2] = {0, 0};
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const auto& alone = x < kSize / 2 ? leftOnly.at(x, y) : rightOnly.at(x, y);
        if (alone.w <= 0.0f) continue;
        ++covered[x < kSize / 2 ? 0 : 1];
        worst = std::max(worst, static_cast<double>(std::abs(both.at(x, y).x - alone.x)));
      }
    EXPECT_GT(covered[0], 2000);
    EXPECT_GT(covered[1], 2000);
    return worst;
  };
  EXPECT_LT(worstAgainstAlone(litObject, parallaxObject), 1e-3);
  // Two parallax objects with lightmaps of different sizes: each keeps its own.
  render::SceneObject second = parallaxObject;
  second.mesh = *a;
  std::get<render::ParallaxSettings>(second.method).lightmap.size = 256;
  std::get<render::ParallaxSettings>(second.method).lightmap.reduction = 2;
  EXPECT_LT(worstAgainstAlone(second, parallaxObject), 1e-3);
}

TEST_P(ParallaxTest, InnerLayersCompositeByTheirOpacities) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  const SphereMesh sphere = makeSphere(40.0f, 32, 64);
  auto mesh = renderer->createMesh(sphere.arrays());
  auto vessels = renderer->createTexture(vesselTexture(128));
  auto grey = renderer->createTexture(solid(90));
  ASSERT_TRUE(mesh && vessels && grey);
  render::Scene scene = goldenScene();
  render::SceneObject o;
  o.mesh = *mesh;
  scene.objects = {o};
  auto image = [&](std::vector<render::ParallaxLayer> layers) {
    render::ParallaxSettings s;
    s.opacity = 0.2f;
    s.layers = std::move(layers);
    scene.objects[0].method = s;
    auto r = renderer->renderImage(scene, 128, 128);
    EXPECT_TRUE(r) << (r ? "" : r.error().message);
    return r ? *r : Image8{};
  };
  const Image8 shallow = image({{*vessels, 1.0f, 1.0f}}), deep = image({{*grey, 3.0f, 1.0f}});
  // A transparent shallow layer shows the deep one; an opaque one hides it; the deepest layer is
  // always opaque.
  EXPECT_EQ(compareImages(image({{*vessels, 1.0f, 0.0f}, {*grey, 3.0f, 1.0f}}), deep, 0).maxDiff, 0);
  EXPECT_EQ(compareImages(image({{*vessels, 1.0f, 1.0f}, {*grey, 3.0f, 0.0f}}), shallow, 0).maxDiff, 0);
  const Image8 half = image({{*vessels, 1.0f, 0.5f}, {*grey, 3.0f, 1.0f}});
  EXPECT_GT(meanDifference(half, shallow), 0.2);
  EXPECT_GT(meanDifference(half, deep), 0.2);
}

TEST_P(ParallaxTest, BadSettingsAreOneClearError) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  const SphereMesh sphere = makeSphere(20.0f, 8, 16);
  auto mesh = renderer->createMesh(sphere.arrays());
  ASSERT_TRUE(mesh);
  render::Scene scene = angledScene(0.0f);
  render::SceneObject o;
  o.mesh = *mesh;
  render::ParallaxSettings s;
  s.layers = {{{}, 2.0f, 0.5f}, {{}, 1.0f, 1.0f}};  // not increasing
  o.method = s;
  scene.objects = {o};
  auto image = renderer->renderImage(scene, 64, 64);
  ASSERT_FALSE(image);
  EXPECT_NE(image.error().message.find("increasing"), std::string::npos) << image.error().message;
  s.layers = {{render::TextureHandle{777}, 1.0f, 1.0f}};  // a texture this renderer lacks
  scene.objects[0].method = s;
  image = renderer->renderImage(scene, 64, 64);
  ASSERT_FALSE(image);
  EXPECT_NE(image.error().message.find("777"), std::string::npos) << image.error().message;
}

INSTANTIATE_TEST_SUITE_P(Backends, ParallaxTest, ::testing::Values(Backend::Egl, Backend::OsMesa),
                         backendParamName);

}  // namespace
}  // namespace tissue::test
