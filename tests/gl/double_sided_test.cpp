// Open surfaces render from both sides (issue 14): a flat patch seen from behind, with the light
// on the camera's side, must look like the patch seen from the front with the light mirrored
// (the back face shades with the negated normal), for every shading method; without
// SceneObject::doubleSided the back view stays culled (closed meshes keep the cheaper default).
#include <cstdio>
#include <string>

#include "embedding_scene.h"
#include "gl_test_support.h"
#include "image_compare.h"

namespace tissue::test {
namespace {

constexpr int kSize = 96;

struct Coverage {
  int pixels = 0;     ///< pixels brighter than the background by more than 12 grey levels
  double mean = 0.0;  ///< mean of R + G + B over them, grey levels
};

Coverage coverage(const Image8& image, const Float3& background) {
  Coverage c;
  const int bg = int(background.x * 255.0f + 0.5f) + int(background.y * 255.0f + 0.5f) +
                 int(background.z * 255.0f + 0.5f);
  double sum = 0.0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const auto p = image.at(x, y);
      const int v = int(p[0]) + int(p[1]) + int(p[2]);
      if (v > bg + 12) {
        ++c.pixels;
        sum += v;
      }
    }
  c.mean = c.pixels > 0 ? sum / c.pixels : 0.0;
  return c;
}

// The camera and the key light on one side of the patch (z = 0, facing +z): side = +1 in front,
// -1 behind. Mirroring z maps one scene onto the other.
render::Scene sideScene(float side) {
  render::Scene scene = goldenScene();
  scene.camera.eye = {0.0f, -20.0f, 110.0f * side};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.camera.up = {0.0f, 1.0f, 0.0f};
  scene.lights.resize(1);
  scene.lights[0].positionMm = {60.0f, 90.0f, 220.0f * side};
  scene.lights[0].castsShadows = false;
  return scene;
}

class DoubleSidedTest : public ::testing::TestWithParam<render::ShadingMethod> {};

TEST_P(DoubleSidedTest, TheBackOfAnOpenPatchShadesLikeItsFront) {
  const render::ShadingMethod method = GetParam();
  TISSUE_CONTEXT_OR_FAIL(context, Backend::Egl);
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  auto textures = uploadMethodTextures(*renderer);
  ASSERT_TRUE(textures) << textures.error().message;
  const SphereMesh patch = makePatch(60.0f, 16, 0.0f);
  render::MeshArrays arrays = patch.arrays();
  std::vector<Float4> planes(patch.positions.size(),
                             Float4{0.0f, 0.0f, 1.0f, 0.3f});  // the patch's own plane
  arrays.planes = planes;
  auto mesh = renderer->createMesh(arrays);
  ASSERT_TRUE(mesh) << mesh.error().message;
  render::SceneObject object = methodObject(method, *mesh, *textures, 1.0f / 60.0f);

  auto render = [&](float side, bool doubleSided) {
    render::Scene scene = sideScene(side);
    object.doubleSided = doubleSided;
    scene.objects = {object};
    auto image = renderer->renderImage(scene, kSize, kSize);
    EXPECT_TRUE(image) << image.error().message;
    return image ? coverage(*image, scene.background) : Coverage{};
  };
  const Coverage front = render(1.0f, true), back = render(-1.0f, true);
  const Coverage culledBack = render(-1.0f, false), culledFront = render(1.0f, false);
  std::printf("[ double-sided ] %s: front %d px mean %.1f; back %d px mean %.1f; culled back %d px\n",
              std::string(render::shadingMethodName(method)).c_str(), front.pixels, front.mean, back.pixels,
              back.mean, culledBack.pixels);
  ASSERT_GT(front.pixels, kSize * kSize / 4) << "the patch fills a good part of the frame";
  // Seen from behind it covers the same pixels (mirrored) and is about as bright: the textures
  // are mirrored and the normal map's bumps become dents, so the mean differs a little.
  EXPECT_NEAR(back.pixels, front.pixels, 0.02 * front.pixels);
  EXPECT_NEAR(back.mean, front.mean, 0.1 * front.mean);
  // Double-sided drawing changes nothing from the front.
  EXPECT_EQ(culledFront.pixels, front.pixels);
  EXPECT_NEAR(culledFront.mean, front.mean, 0.5);
  // The default culls the back: the patch vanishes from behind.
  EXPECT_LT(culledBack.pixels, front.pixels / 50);
}

INSTANTIATE_TEST_SUITE_P(Methods, DoubleSidedTest, ::testing::ValuesIn(kAllMethods),
                         [](const auto& p) { return methodTestName(p.param); });

}  // namespace
}  // namespace tissue::test
