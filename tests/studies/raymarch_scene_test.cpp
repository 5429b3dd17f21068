// The organ ready for ray marching (studies/raymarch_scene.h) on the data liver: its layer stack
// and subsurface map come through the scene module's organ layer, the camera frames the organ
// (the close-up nearer the poke site), the poke pushes the site no deeper than asked, an organ
// without a subsurface map is refused, and on a headless context the pipeline renders the organ
// over the background.
#include "tissue/studies/raymarch_scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <vector>

#include "tissue/context/headless_context.h"
#include "tissue/core/vec_math.h"
#include "tissue/scene/material_file.h"

namespace tissue::studies {
namespace {

scene::OrganSource dataLiver() {
  const std::filesystem::path data = TISSUE_TEST_DATA_DIR;
  scene::OrganSource source;
  source.mesh = data / "meshes" / "liver.obj";
  source.material = data / "materials" / "liver.json";
  source.materialOptions.textureRoots = {TISSUE_TEST_GENERATED_DATA_DIR, data};
  return source;
}

float distanceOf(Float3 a, Float3 b) {
  return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}

TEST(RayMarchScene, LoadsTheLayerStackAndFramesTheOrgan) {
  auto whole = loadRayMarchScene(dataLiver(), 4.0f / 3.0f, false);
  ASSERT_TRUE(whole) << whole.error().message;
  ASSERT_NE(whole->surface, nullptr);
  EXPECT_EQ(whole->surface, whole->owned.get());
  EXPECT_FALSE(whole->material.stack.layers.empty());
  EXPECT_GT(whole->material.subsurfaceMap.width, 0);
  EXPECT_GT(whole->material.uvPerMm, 0.0f);
  // The whole-organ camera looks at the centre of the rest shape's box.
  const Bounds3 box = boundsOf(whole->surface->geometricRestPositions());
  const Float3 centre{(box.lo.x + box.hi.x) / 2, (box.lo.y + box.hi.y) / 2, (box.lo.z + box.hi.z) / 2};
  EXPECT_LT(distanceOf(whole->camera.target, centre), 1e-3f * distanceOf(box.lo, box.hi));
  // The poke site is the top vertex; the close-up looks at it from nearer.
  const auto rest = whole->surface->geometricRestPositions();
  ASSERT_LT(whole->pokeSite, rest.size());
  for (const Float3& p : rest)
    EXPECT_LE(p.z, rest[whole->pokeSite].z);
  auto close = loadRayMarchScene(dataLiver(), 4.0f / 3.0f, true);
  ASSERT_TRUE(close) << close.error().message;
  EXPECT_LT(distanceOf(close->camera.eye, rest[close->pokeSite]),
            distanceOf(whole->camera.eye, rest[whole->pokeSite]));
  // Two lights, the key one brighter; the pipeline's copies carry the same radiance.
  ASSERT_EQ(whole->lights.size(), 2u);
  EXPECT_GT(whole->lights[0].radiance.x, whole->lights[1].radiance.x);
  const auto lights = pipelineLights(*whole);
  ASSERT_EQ(lights.size(), 2u);
  EXPECT_EQ(lights[1].color.y, whole->lights[1].radiance.y);
  // The march settings carry the whole stack and the mesh's texture scale.
  const render::RayMarchSettings march = withMaterial({}, *whole, {});
  EXPECT_EQ(march.layers.size(), whole->material.stack.layers.size());
  EXPECT_EQ(march.uvPerMm, whole->material.uvPerMm);
  EXPECT_EQ(meshView(*whole).positions.size(), whole->surface->positions().size());
}

TEST(RayMarchScene, PokePushesTheSiteNoDeeperThanAsked) {
  auto scene = loadRayMarchScene(dataLiver(), 1.0f, true);
  ASSERT_TRUE(scene) << scene.error().message;
  const std::vector<Float3> before(scene->surface->geometricPositions().begin(),
                                   scene->surface->geometricPositions().end());
  const float depth = 8.0f;  // mm
  ASSERT_TRUE(pokeScene(*scene, 0.02, depth));
  const auto after = scene->surface->geometricPositions();
  float deepest = 0.0f;
  std::size_t moved = 0;
  for (std::size_t i = 0; i < after.size(); ++i) {
    const float d = distanceOf(before[i], after[i]);
    deepest = std::max(deepest, d);
    moved += d > 1e-6f ? 1 : 0;
  }
  EXPECT_NEAR(distanceOf(before[scene->pokeSite], after[scene->pokeSite]), depth, 1e-3f);
  EXPECT_LE(deepest, depth * 1.0001f);
  EXPECT_GT(moved, 1u);
  EXPECT_LT(moved, after.size() / 10);  // about 2 % of the vertices
}

TEST(RayMarchScene, RefusesAnOrganWithoutSubsurfaceMap) {
  auto loaded = loadRayMarchScene(dataLiver(), 1.0f, false);
  ASSERT_TRUE(loaded) << loaded.error().message;
  scene::OrganAssets organ;
  organ.material = scene::defaultMaterial();
  auto scene = rayMarchSceneFor(*loaded->surface, organ, 1.0f, false);
  ASSERT_FALSE(scene);
  EXPECT_NE(scene.error().message.find("textures.subsurface"), std::string::npos) << scene.error().message;
  // A scene on a surface it does not own cannot poke it.
  auto assets = scene::loadOrganAssets(dataLiver());
  ASSERT_TRUE(assets) << assets.error().message;
  auto borrowed = rayMarchSceneFor(*loaded->surface, *assets, 1.0f, false);
  ASSERT_TRUE(borrowed) << borrowed.error().message;
  EXPECT_FALSE(pokeScene(*borrowed, 0.02, 4.0f));
}

TEST(RayMarchSceneGl, RendersTheOrganOverTheBackground) {
  auto scene = loadRayMarchScene(dataLiver(), 4.0f / 3.0f, false);
  ASSERT_TRUE(scene) << scene.error().message;
  auto context = context::createHeadlessContext({}, {.backend = "", .log = false});
  ASSERT_TRUE(context) << "no headless context (EGL, then OSMesa): " << context.error().message;
  auto gpu = makeRayMarchRender(*scene, (*context)->procAddressFunction());
  ASSERT_TRUE(gpu) << gpu.error().message;
  render::RayMarchSettings march;
  march.samples = 8;
  gpu->setMarch(march);
  EXPECT_EQ(gpu->settings().layers.size(), scene->material.stack.layers.size());  // the material kept
  const int w = 48, h = 36;
  auto image = gpu->render(w, h);
  ASSERT_TRUE(image) << image.error().message;
  ASSERT_EQ(image->width, w);
  // The corner is background; the organ covers a good part of the frame, and differs from it.
  const auto corner = image->at(0, 0);
  int organ = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const auto p = image->at(x, y);
      organ += (std::abs(int(p[0]) - int(corner[0])) + std::abs(int(p[1]) - int(corner[1])) +
                std::abs(int(p[2]) - int(corner[2]))) > 12;
    }
  EXPECT_GT(organ, w * h / 10);
  EXPECT_LT(organ, w * h);
  EXPECT_NEAR(double(corner[0]), 255.0 * double(kRayMarchBackground.x), 3.0);  // sRGB already
}

}  // namespace
}  // namespace tissue::studies
