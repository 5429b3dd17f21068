// The render pipeline: several objects with per-object methods, named and timed passes,
// shadow maps from point and directional lights, partial mesh updates, and methods not in
// this build failing loudly instead of drawing something else.
#include <algorithm>

#include "gl_test_support.h"
#include "image_compare.h"
#include "test_scene.h"

namespace tissue::test {
namespace {

constexpr int kSize = 128;

// Camera on +z looking at the origin, where the patch lies.
render::Scene frontScene() {
  render::Scene scene;
  scene.camera.eye = {0.0f, 0.0f, 200.0f};
  scene.camera.nearMm = 50.0f;
  scene.camera.farMm = 400.0f;
  return scene;
}

render::SceneObject object(render::MeshHandle mesh) {
  render::SceneObject o;
  o.mesh = mesh;
  return o;
}

render::RendererSettings withShadowMap(int size) {
  render::RendererSettings settings;
  settings.shadowMapSize = size;
  return settings;
}

render::MeshUpdate normalsFrom(std::size_t first, std::span<const Float3> normals) {
  render::MeshUpdate u;
  u.firstVertex = first;
  u.normals = normals;
  return u;
}

// Mean red level over a square of `half` pixels around (x, y).
double meanRed(const Image8& image, int x, int y, int half) {
  double sum = 0.0;
  int n = 0;
  for (int j = y - half; j <= y + half; ++j)
    for (int i = x - half; i <= x + half; ++i, ++n)
      sum += image.at(i, j)[0];
  return sum / n;
}

class PipelineTest : public ::testing::TestWithParam<Backend> {};

TEST_P(PipelineTest, TimingsListEveryPassInOrder) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto renderer = render::Renderer::create(context->procAddressFunction(), withShadowMap(256));
  ASSERT_TRUE(renderer) << renderer.error().message;
  const SphereMesh patch = makePatch(120.0f, 4, 0.0f), sphere = makeSphere(15.0f, 16, 32);
  auto a = renderer->createMesh(patch.arrays());
  auto b = renderer->createMesh(sphere.arrays());
  ASSERT_TRUE(a && b);
  render::Scene scene = frontScene();
  scene.objects = {object(*a), object(*b)};
  scene.lights.resize(2);
  scene.lights[0].castsShadows = true;
  scene.lights[1].type = render::LightType::Directional;
  scene.lights[1].castsShadows = true;
  ASSERT_TRUE(renderer->renderImage(scene, kSize, kSize));
  std::vector<std::string> names;
  for (const auto& p : renderer->lastTimings().passes) {
    names.push_back(p.name);
    EXPECT_GE(p.cpuMs, 0.0) << p.name;
    EXPECT_EQ(p.object, -1) << p.name << ": no pass here is one object's alone";
  }
  const std::vector<std::string> expected = {"shadow:0",  "shadow:1", "clear",   "lit",
                                             "composite", "tonemap",  "readback"};
  EXPECT_EQ(names, expected);
  // The lit pass draws both objects: each one's issue time, in draw order, within the pass's.
  const render::PassTiming* lit = renderer->lastTimings().find("lit");
  ASSERT_NE(lit, nullptr);
  ASSERT_EQ(lit->issued.size(), 2u);
  double issued = 0.0;
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(lit->issued[i].first, int(i));
    EXPECT_GE(lit->issued[i].second, 0.0);
    issued += lit->issued[i].second;
  }
  EXPECT_LE(issued, lit->cpuMs + 1e-9);
  EXPECT_NE(renderer->lastTimings().find("lit"), nullptr);
  EXPECT_EQ(renderer->lastTimings().find("separable:blur-x"), nullptr);
}

TEST_P(PipelineTest, UnknownMeshHandleIsAnError) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  const SphereMesh sphere = makeSphere(30.0f, 16, 32);
  auto mesh = renderer->createMesh(sphere.arrays());
  ASSERT_TRUE(mesh);
  render::Scene scene = frontScene();
  scene.objects = {object(*mesh)};
  ASSERT_TRUE(renderer->renderImage(scene, kSize, kSize));
  // An object naming a mesh this renderer does not hold is an error, not a skipped object.
  scene.objects[0] = object(render::MeshHandle{999});
  EXPECT_FALSE(renderer->renderImage(scene, kSize, kSize));
}

TEST_P(PipelineTest, ShadowMapsDarkenTheGroundBehindAnOccluder) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto renderer = render::Renderer::create(context->procAddressFunction(), withShadowMap(512));
  ASSERT_TRUE(renderer) << renderer.error().message;
  const SphereMesh patch = makePatch(140.0f, 8, 0.0f);
  SphereMesh sphere = makeSphere(12.0f, 16, 32);
  for (auto& p : sphere.positions)
    p.z += 30.0f;  // mm above the patch
  auto a = renderer->createMesh(patch.arrays());
  auto b = renderer->createMesh(sphere.arrays());
  ASSERT_TRUE(a && b);
  render::Scene scene = frontScene();
  scene.objects = {object(*a), object(*b)};
  // Light travelling toward +x and -z: the shadow falls 30 * 0.75 = 22.5 mm right of the sphere.
  for (const auto type : {render::LightType::Directional, render::LightType::Point}) {
    render::Light& light = scene.lights[0];
    light.type = type;
    light.direction = {0.6f, 0.0f, -0.8f};
    light.positionMm = {-0.6f * 1000.0f, 0.0f, 30.0f + 0.8f * 1000.0f};  // far along the same line
    light.castsShadows = false;
    auto lit = renderer->renderImage(scene, kSize, kSize);
    light.castsShadows = true;
    auto shadowed = renderer->renderImage(scene, kSize, kSize);
    ASSERT_TRUE(lit && shadowed) << (lit ? shadowed.error().message : lit.error().message);
    // 0.88 px per mm at the patch: the shadow's centre is near pixel x = 64 + 20.
    const double inShadow = meanRed(*shadowed, 84, 64, 2), wasLit = meanRed(*lit, 84, 64, 2);
    EXPECT_LT(inShadow, wasLit * 0.6) << "light type " << static_cast<int>(type);
    // Far from the shadow nothing changes.
    EXPECT_NEAR(meanRed(*shadowed, 20, 20, 2), meanRed(*lit, 20, 20, 2), 1.0);
  }
}

TEST_P(PipelineTest, PartialMeshUpdatesTouchOnlyTheirRange) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  SphereMesh patch = makePatch(120.0f, 10, 0.0f);
  auto mesh = renderer->createMesh(patch.arrays());
  ASSERT_TRUE(mesh);
  render::Scene scene = frontScene();
  scene.objects = {object(*mesh)};
  auto before = renderer->renderImage(scene, kSize, kSize);
  // Tilt the normals of the top row only (vertices 110..120): only the top of the image changes.
  std::vector<Float3> tilted(11, Float3{0.0f, 0.8f, 0.6f});
  ASSERT_TRUE(renderer->updateMesh(*mesh, normalsFrom(110, tilted)));
  auto after = renderer->renderImage(scene, kSize, kSize);
  ASSERT_TRUE(before && after);
  EXPECT_EQ(meanRed(*before, 64, 100, 3), meanRed(*after, 64, 100, 3));  // bottom rows: untouched
  EXPECT_NE(meanRed(*before, 64, 16, 3), meanRed(*after, 64, 16, 3));    // top band (y 48..60 mm): re-shaded
  // Past the end is an Error; so are planes on a mesh made without them.
  EXPECT_FALSE(renderer->updateMesh(*mesh, normalsFrom(115, tilted)));
  std::vector<Float4> planes(3);
  render::MeshUpdate withPlanes;
  withPlanes.planes = planes;
  EXPECT_FALSE(renderer->updateMesh(*mesh, withPlanes));
}

INSTANTIATE_TEST_SUITE_P(Backends, PipelineTest, ::testing::Values(Backend::Egl, Backend::OsMesa),
                         backendParamName);

}  // namespace
}  // namespace tissue::test
