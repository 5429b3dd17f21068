// A scene under a frame budget (issue 16): the controller chooses each organ's method, a far
// organ falls back to the lit tier (wrap where the table says it helps), the budget is refused when it is not
// a number of ms, and the wrap term lights past the terminator. Needs GL (the scene's own headless context).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>

#include "tissue/scene/scene.h"

namespace tissue::scene {
namespace {

const std::filesystem::path kData = TISSUE_TEST_DATA_DIR;

Mat4 translation(Float3 t) {
  Mat4 m = kIdentity4;
  m[12] = t.x, m[13] = t.y, m[14] = t.z;
  return m;
}

Scene threeLivers() {
  SceneSettings settings;
  settings.materials.textureRoots = {TISSUE_TEST_GENERATED_DATA_DIR, TISSUE_TEST_DATA_DIR};
  settings.renderer.finishPasses = true;    // llvmpipe: the pass times are what the controller learns
  settings.quality.minFootprintPx = 400.0;  // the far liver (6 m away) below it
  auto scene = Scene::create({}, settings);
  EXPECT_TRUE(scene.ok()) << (scene ? "" : scene.error().message);
  for (float z : {0.0f, -600.0f, -6000.0f}) {
    OrganDesc d;
    d.mesh = kData / "meshes" / "liver.obj";
    d.material = kData / "materials" / "liver.json";
    d.model = translation({0.0f, 0.0f, z});
    EXPECT_TRUE(scene->addOrgan(d).ok());
  }
  render::Camera cam;
  cam.eye = {0.0f, 0.0f, 350.0f};
  cam.target = {0.0f, 0.0f, 0.0f};
  cam.farMm = 10000.0f;
  scene->setCamera(cam);
  return std::move(*scene);
}

double meanLevel(const Image8& image) {
  double sum = 0.0;
  for (std::uint8_t v : image.pixels)
    sum += v;
  return sum / double(image.pixels.size());
}

TEST(SceneBudget, TheControllerChoosesPerOrganAndTheFarOneFallsBackToTheLitTier) {
  Scene scene = threeLivers();
  EXPECT_TRUE(scene.budgetChoices().empty());
  ASSERT_TRUE(scene.setBudgetMs(1000.0).ok());
  for (int f = 0; f < 3; ++f)
    ASSERT_TRUE(scene.renderImage(240, 180).ok());
  const auto& choices = scene.budgetChoices();
  ASSERT_EQ(choices.size(), 3u);
  EXPECT_GT(choices[0].footprintPx, choices[1].footprintPx);
  EXPECT_GT(choices[1].footprintPx, choices[2].footprintPx);
  EXPECT_TRUE(choices[2].fallback);
  EXPECT_EQ(choices[2].method, "lit");
  // Of lit's two settings the one the table's error for the organ's view prefers.
  const quality::QualityTable& table = scene.qualityController()->table();
  const std::optional<quality::ViewClass> viewClass = quality::viewClassOfFrame(choices[2].view);
  ASSERT_TRUE(viewClass) << choices[2].view;
  const auto view = std::size_t(*viewClass);
  // (as charged: the squared error plus one standard error of the atlas's paired difference)
  const auto charged = [&](const char* setting) {
    const quality::QualityOption& o = table.options[std::size_t(table.find("lit", setting))];
    return o.relRms[view] * o.relRms[view] + o.squaredStderr[view];
  };
  const double wrapError = charged("wrap"), plainError = charged("default");
  EXPECT_EQ(choices[2].setting, wrapError < plainError ? "wrap" : "default")
      << "wrap " << wrapError << ", default " << plainError << " on " << choices[2].view;
  EXPECT_FALSE(choices[0].fallback);
  EXPECT_EQ(choices[0].mesh.planes, choices[0].method == "ray-march");
  // The controller has measured something.
  ASSERT_NE(scene.qualityController(), nullptr);
  int measured = 0;
  for (const auto& c : scene.qualityController()->costs())
    measured += c.samples > 0 ? 1 : 0;
  EXPECT_GE(measured, 1);
  // Off again: the choices go, the organs keep their methods.
  ASSERT_TRUE(scene.setBudgetMs(0.0).ok());
  EXPECT_TRUE(scene.budgetChoices().empty());
  EXPECT_TRUE(scene.renderImage(240, 180).ok());
}

// Frames whose organs the host set to table options (no budget) teach the controller those
// options' costs; the first frame of an option (its one-off work) teaches nothing; an organ with a
// method of its own (setMethod) stops the learning, its cost not being any option's.
TEST(SceneBudget, FramesOfOptionsTheHostChoseTeachTheControllerTheirCosts) {
  Scene scene = threeLivers();
  const quality::QualityTable& table = quality::defaultQualityTable();
  const int lit = table.find("lit", "default"), sep = table.find("separable", "preintegrated-17");
  ASSERT_GE(lit, 0);
  ASSERT_GE(sep, 0);
  ASSERT_TRUE(scene.setMethodOption(0, table.options[std::size_t(sep)]).ok());
  for (OrganId o : {OrganId(1), OrganId(2)})
    ASSERT_TRUE(scene.setMethodOption(o, table.options[std::size_t(lit)]).ok());
  ASSERT_NE(scene.qualityController(), nullptr);
  const auto samples = [&](int option) {
    return scene.qualityController()->costs()[std::size_t(option)].samples;
  };
  ASSERT_TRUE(scene.renderImage(240, 180).ok());  // every option new: nothing learned
  EXPECT_EQ(samples(sep), 0);
  EXPECT_EQ(samples(lit), 0);
  for (int f = 0; f < 4; ++f)
    ASSERT_TRUE(scene.renderImage(240, 180).ok());
  EXPECT_EQ(samples(sep), 4);
  EXPECT_GE(samples(lit), 8);  // two organs a frame (and its cost class's siblings with it)
  EXPECT_GT(scene.qualityController()->costs()[std::size_t(sep)].predictMs(1000.0), 0.0);
  // A method of its own on one organ: no frame is learned from.
  ASSERT_TRUE(scene.setMethod(2, render::ShadingMethod::Lit).ok());
  for (int f = 0; f < 2; ++f)
    ASSERT_TRUE(scene.renderImage(240, 180).ok());
  EXPECT_EQ(samples(sep), 4);
  EXPECT_TRUE(scene.budgetChoices().empty());
}

// An option's settings are a CPU fit (separable kernels, texture space's Gaussians: 9-104 ms);
// they are built on the scene's worker from the budget on, and the controller is offered the
// built ones, so that no frame waits for a fit. A host's loading screen may wait for them all.
TEST(SceneBudget, OptionSettingsAreBuiltOffTheFramePathFromTheBudgetOn) {
  Scene scene = threeLivers();
  EXPECT_EQ(scene.budgetOptionsPending(), 0u);  // no budget: nothing offered yet
  ASSERT_TRUE(scene.setBudgetMs(1000.0).ok());
  // Every organ's offered options are queued at once (lit's built at once): some hundred fits,
  // each a millisecond or more, are not done by the time setBudgetMs returns.
  EXPECT_GT(scene.budgetOptionsPending(), 0u);
  ASSERT_TRUE(scene.renderImage(240, 180).ok());  // a frame meanwhile chooses among the built ones
  ASSERT_EQ(scene.budgetChoices().size(), 3u);
  ASSERT_TRUE(scene.prepareBudgetOptions().ok());
  EXPECT_EQ(scene.budgetOptionsPending(), 0u);
  // All built: the close organ, under a budget anything fits, takes a method that scatters light
  // (the table's error puts lit behind every other method on every frame).
  for (int f = 0; f < 3; ++f)
    ASSERT_TRUE(scene.renderImage(240, 180).ok());
  EXPECT_NE(scene.budgetChoices()[0].method, "lit");
  EXPECT_EQ(scene.budgetOptionsPending(), 0u);
}

TEST(SceneBudget, ABudgetMustBeAFiniteNumberOfMs) {
  Scene scene = threeLivers();
  EXPECT_FALSE(scene.setBudgetMs(-1.0).ok());
  EXPECT_FALSE(scene.setBudgetMs(std::nan("")).ok());
  EXPECT_TRUE(scene.setBudgetMs(16.0).ok());
  EXPECT_EQ(scene.budgetMs(), 16.0);
}

TEST(SceneBudget, WrapLightsPastTheTerminator) {
  SceneSettings settings;
  settings.materials.textureRoots = {TISSUE_TEST_GENERATED_DATA_DIR, TISSUE_TEST_DATA_DIR};
  auto scene = Scene::create({}, settings);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  OrganDesc d;
  d.mesh = kData / "meshes" / "liver.obj";
  d.material = kData / "materials" / "liver.json";
  // A liver 1/50 of its size (about 4 mm): light diffuses across a good part of it, so its
  // optical wrap (opticalWrap) is clamped at Green's half wrap, large enough to see in the mean.
  d.meshScaleToMm = 0.02f;
  ASSERT_TRUE(scene->addOrgan(d).ok());  // lit, no wrap
  auto plain = scene->renderImage(160, 120);
  ASSERT_TRUE(plain.ok()) << plain.error().message;
  const quality::QualityTable& table = quality::defaultQualityTable();
  ASSERT_TRUE(scene->setMethodOption(0, table.options[std::size_t(table.find("lit", "wrap"))]).ok());
  auto wrapped = scene->renderImage(160, 120);
  ASSERT_TRUE(wrapped.ok()) << wrapped.error().message;
  // (N.L + w) / (1 + w) >= N.L: brighter where the light grazes, never darker.
  EXPECT_GT(meanLevel(*wrapped), meanLevel(*plain) + 0.2);
}

// SceneSettings::normalMaps off (the atlas and the budget bench: the truth has no normal map):
// the organ is drawn off the mesh's own shape and its lit method needs no tangent frames.
TEST(SceneNormalMaps, OffDrawsTheMeshShapeAndDropsTheTangents) {
  std::optional<Image8> images[2];
  for (bool maps : {true, false}) {
    SceneSettings settings;
    settings.materials.textureRoots = {TISSUE_TEST_GENERATED_DATA_DIR, TISSUE_TEST_DATA_DIR};
    settings.quality.minFootprintPx = 1e12;  // lit (wrap), whose tangents follow the normal map
    settings.normalMaps = maps;
    auto scene = Scene::create({}, settings);
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    OrganDesc d;
    d.mesh = kData / "meshes" / "liver.obj";
    d.material = kData / "materials" / "liver.json";  // has a normal map
    ASSERT_TRUE(scene->addOrgan(d).ok());
    ASSERT_TRUE(scene->setBudgetMs(1e4).ok());
    auto image = scene->renderImage(160, 120);
    ASSERT_TRUE(image.ok()) << image.error().message;
    ASSERT_EQ(scene->budgetChoices().size(), 1u);
    EXPECT_EQ(scene->budgetChoices()[0].mesh.tangents, maps);
    images[maps ? 0 : 1] = std::move(*image);
  }
  ASSERT_EQ(images[0]->pixels.size(), images[1]->pixels.size());
  // The map's bumps move the shading of a good part of the organ's pixels.
  int organ = 0, moved = 0;
  for (std::size_t i = 0; i + 3 < images[0]->pixels.size(); i += 4) {
    bool differs = false, covered = false;
    for (std::size_t c = 0; c < 3; ++c) {
      differs = differs || images[0]->pixels[i + c] != images[1]->pixels[i + c];
      covered = covered || images[1]->pixels[i + c] != images[1]->pixels[c];  // not the corner's background
    }
    organ += covered ? 1 : 0;
    moved += differs ? 1 : 0;
  }
  std::printf("normal maps: %d of %d organ pixels change\n", moved, organ);
  EXPECT_GT(moved, organ / 4);
}

}  // namespace
}  // namespace tissue::scene
