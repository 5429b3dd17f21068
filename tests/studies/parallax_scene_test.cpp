// The organ ready for layered parallax (studies/parallax_scene.h): the data patch brings its
// material's layer textures on its own UVs; a mesh without UVs gets the atlas and no textures;
// on a headless context the scene holds one parallax object with the asked layer depth and the
// inner layer's texture, and renders the organ over the background.
#include "tissue/studies/parallax_scene.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <variant>

#include "data_organ.h"
#include "tissue/context/headless_context.h"

namespace tissue::studies {
namespace {

scene::OrganSource dataPatch() {
  const std::filesystem::path data = TISSUE_TEST_DATA_DIR;
  scene::OrganSource source;
  source.mesh = data / "meshes" / "patch.obj";
  source.material = data / "materials" / "patch.json";
  source.materialOptions.textureRoots = {TISSUE_TEST_GENERATED_DATA_DIR, data};
  return source;
}

TEST(ParallaxScene, ThePatchBringsItsLayerTextures) {
  auto organ = loadParallaxOrgan(dataPatch());
  ASSERT_TRUE(organ) << organ.error().message;
  EXPECT_FALSE(organ->organ.atlas);
  EXPECT_TRUE(organ->textured);
  ASSERT_TRUE(organ->innerBase.has_value());
  EXPECT_GT(organ->innerBase->width, 0);
  EXPECT_EQ(organ->organ.normals.size(), organ->organ.mesh.positions.size());
}

TEST(ParallaxScene, AMeshWithoutUvsIsUntextured) {
  const auto dir = std::filesystem::path(TISSUE_TEST_OUTPUT_DIR) / "studies";
  std::filesystem::create_directories(dir);
  const auto path = dir / "parallax_tetrahedron.obj";
  std::ofstream(path) << "v 0 0 0\nv 10 0 0\nv 0 10 0\nv 0 0 10\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n";
  scene::OrganSource source;
  source.mesh = path;  // no material: the default organ
  auto organ = loadParallaxOrgan(source);
  ASSERT_TRUE(organ) << organ.error().message;
  EXPECT_TRUE(organ->organ.atlas);
  EXPECT_FALSE(organ->textured);
  EXPECT_FALSE(organ->innerBase.has_value());
}

TEST(ParallaxSceneGl, OneParallaxObjectWithTheInnerLayer) {
  auto organ = loadParallaxOrgan(dataPatch());
  ASSERT_TRUE(organ) << organ.error().message;
  auto context = context::createHeadlessContext({}, {.backend = "", .log = false});
  ASSERT_TRUE(context) << "no headless context (EGL, then OSMesa): " << context.error().message;
  auto renderer = render::Renderer::create((*context)->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  ParallaxOptions options;
  options.layerDepthMm = 2.5f;
  auto scene = makeParallaxScene(*renderer, *organ, options, 4.0f / 3.0f);
  ASSERT_TRUE(scene) << scene.error().message;
  ASSERT_EQ(scene->objects.size(), 1u);
  const auto* parallax = std::get_if<render::ParallaxSettings>(&scene->objects[0].method);
  ASSERT_NE(parallax, nullptr);
  ASSERT_EQ(parallax->layers.size(), 1u);
  EXPECT_EQ(parallax->layers[0].depthMm, 2.5f);
  EXPECT_TRUE(bool(parallax->layers[0].base));
  // Lit, the patch covers part of the frame, unlike the background corner.
  render::Light light;
  light.type = render::LightType::Directional;
  scene->lights = {light};
  const int w = 48, h = 36;
  auto image = renderer->renderImage(*scene, w, h);
  ASSERT_TRUE(image) << image.error().message;
  const auto* corner = image->at(0, 0);
  int organPixels = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const auto* p = image->at(x, y);
      organPixels += std::abs(int(p[0]) - int(corner[0])) + std::abs(int(p[1]) - int(corner[1])) +
                         std::abs(int(p[2]) - int(corner[2])) >
                     12;
    }
  EXPECT_GT(organPixels, w * h / 10);
}

// The study, small: one row per surface x depth x index (4 x 2 x 2), one cell per view angle; on
// the plane the method is exact up to 75 degrees; one CSV line per cell; the four patch images at
// the asked size, listed in the JSON under the caller's folder.
TEST(ParallaxSceneGl, TheStudyAndItsReport) {
  auto context = context::createHeadlessContext({}, {.backend = "", .log = false});
  ASSERT_TRUE(context) << "no headless context (EGL, then OSMesa): " << context.error().message;
  auto renderer = render::Renderer::create((*context)->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  ParallaxStudyRun run;
  run.study.samplePoints = 300;
  run.imageWidth = 40, run.imageHeight = 30;
  run.imageFolder = "out";
  auto study = runParallaxStudy(*renderer, testdata::dataOrgan, run);
  ASSERT_TRUE(study) << study.error().message;
  ASSERT_EQ(study->rows.size(), 16u);
  const std::size_t angles = run.study.viewAnglesDeg.size();
  for (const ParallaxRow& r : study->rows) {
    ASSERT_EQ(r.cells.size(), angles) << r.surface;
    if (r.surface != "plane") continue;
    for (const ParallaxCell& c : r.cells) {
      EXPECT_GT(c.reached, 0) << c.viewAngleDeg;
      if (c.viewAngleDeg <= 75.0f) {
        EXPECT_NEAR(c.meanErrorMm, 0.0, 1e-3) << c.viewAngleDeg;
      }
    }
  }
  EXPECT_EQ(study->rows.back().surface, "tube");
  const Report& report = study->output.report;
  EXPECT_EQ(testdata::lineCount(testdata::fileText(report, "parallax_study.csv")), 16 * angles + 1);
  ASSERT_EQ(report.images.size(), 4u);
  EXPECT_EQ(report.images[3].name, "parallax_patch_85deg.png");
  EXPECT_EQ(report.images[0].image.width, 40);
  EXPECT_NE(study->output.json.find("out/parallax_patch_45deg.png"), std::string::npos);
}

}  // namespace
}  // namespace tissue::studies
