// The renderer's frame as the truth's inputs (scene/truth_view.h), GL-free: a flat patch through
// the adapter is bit for bit the direct truth call with the inputs mapped by hand; the camera,
// light and roughness mappings; bad materials get one line naming the file and the key.
#include <gtest/gtest.h>

#include <cmath>

#include "tissue/scene/truth_view.h"

namespace tissue::scene {
namespace {

// A closed box 40 x 40 x 4 mm whose top face z = 0 is the patch; one layer of the material.
OrganAssets patch() {
  OrganAssets o;
  const float w = 20.0f, z1 = -4.0f;
  o.mesh.positions = {{-w, -w, z1},   {w, -w, z1},   {w, w, z1},   {-w, w, z1},
                      {-w, -w, 0.0f}, {w, -w, 0.0f}, {w, w, 0.0f}, {-w, w, 0.0f}};
  o.mesh.triangles = {{4, 5, 6}, {4, 6, 7}, {0, 2, 1}, {0, 3, 2}, {0, 1, 5}, {0, 5, 4},
                      {2, 3, 7}, {2, 7, 6}, {1, 2, 6}, {1, 6, 5}, {3, 0, 4}, {3, 4, 7}};
  for (const Float3& p : o.mesh.positions)
    o.mesh.uvs.push_back({(p.x + w) / (2 * w), (p.y + w) / (2 * w)});
  o.mesh.geometricIndex = {0, 1, 2, 3, 4, 5, 6, 7};
  o.mesh.geometricVertexCount = 8;
  o.material.file = "patch_test.json";
  o.material.ior = 1.4f;
  MaterialLayer layer;
  layer.sigmaS = {2.0f, 3.0f, 4.0f};
  layer.sigmaT = {2.5f, 3.2f, 5.0f};
  layer.g = 0.7f;
  o.material.layers = {layer};
  o.bounds.add(o.mesh.positions[0]);
  o.bounds.add(o.mesh.positions[6]);
  return o;
}

render::Scene frame() {
  render::Scene s;
  s.camera.eye = {10.0f, -30.0f, 60.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  s.camera.verticalFovDeg = 35.0f;
  render::Light key;  // a point light, then a directional one
  key.positionMm = {50.0f, 40.0f, 120.0f};
  key.color = {1.0f, 0.5f, 0.25f};
  key.intensity = 2.0f;
  render::Light fill;
  fill.type = render::LightType::Directional;
  fill.direction = {0.3f, 0.2f, -1.0f};
  fill.intensity = 0.5f;
  s.lights = {key, fill};
  s.material.shininess = 30.0f;
  return s;
}

truth::PathTraceSettings small() {
  truth::PathTraceSettings s;
  s.width = 12;
  s.height = 9;
  s.samplesPerPass = 2;
  s.passes = 2;
  s.threads = 1;
  s.seed = 3;
  return s;
}

TEST(TruthView, FlatPatchThroughTheAdapterIsTheDirectTruthCall) {
  const OrganAssets organ = patch();
  const render::Scene f = frame();
  auto viaAdapter = renderTruth(organ, organ.mesh.positions, f, small());
  ASSERT_TRUE(viaAdapter.ok()) << viaAdapter.error().message;

  // The same inputs written out by hand.
  truth::TruthMaterial m;
  truth::TruthLayer l;
  l.sigmaS = truth::Rgb{2.0, 3.0, 4.0};
  l.sigmaA = truth::Rgb{0.5, double(3.2f - 3.0f), 1.0};
  l.g = {double(0.7f), double(0.7f), double(0.7f)};
  l.n = double(1.4f);
  m.layers = {l};
  truth::TruthLight key, fill;
  key.positionMm = {50.0f, 40.0f, 120.0f};
  key.radiance = {2.0f, 1.0f, 0.5f};
  fill.type = truth::TruthLightType::Directional;
  fill.direction = {0.3f, 0.2f, -1.0f};
  fill.radiance = Float3{1.0f, 0.97f, 0.92f} * 0.5f;
  const truth::TruthLight lights[2] = {key, fill};
  truth::TruthCamera camera;
  camera.eye = {10.0f, -30.0f, 60.0f};
  camera.verticalFovDeg = 35.0f;
  truth::PathTraceSettings s = small();
  s.surfaceRoughness = std::sqrt(2.0 / 32.0);  // Blinn-Phong 30
  auto direct = truth::renderPathTraced({organ.mesh.positions, organ.mesh.triangles, organ.mesh.uvs}, m,
                                        lights, camera, s);
  ASSERT_TRUE(direct.ok()) << direct.error().message;
  EXPECT_EQ(viaAdapter->covered, direct->covered);
  EXPECT_EQ(viaAdapter->radiance, direct->radiance);
  EXPECT_EQ(viaAdapter->stderrs, direct->stderrs);
  double sum = 0.0;
  for (const Float3& p : direct->radiance)
    sum += double(p.x + p.y + p.z);
  EXPECT_GT(sum, 0.0);
}

TEST(TruthView, MappingsOfCameraLightsAndSurface) {
  const render::Scene f = frame();
  const truth::TruthCamera c = truthCameraOf(f.camera);
  EXPECT_EQ(c.projection, truth::Projection::Pinhole);
  EXPECT_EQ(c.eye.z, 60.0f);
  EXPECT_EQ(c.verticalFovDeg, 35.0f);
  const auto lights = truthLightsOf(f.lights);
  ASSERT_EQ(lights.size(), 2u);
  EXPECT_EQ(lights[0].type, truth::TruthLightType::Point);
  EXPECT_EQ(lights[1].type, truth::TruthLightType::Directional);
  EXPECT_FLOAT_EQ(lights[0].radiance.y, 1.0f);  // colour 0.5 * intensity 2
  EXPECT_TRUE(lights[0].castsShadows && lights[1].castsShadows);
  render::Material smooth;
  smooth.shininess = 1e6f;
  EXPECT_LT(roughnessOf(smooth), 2e-3);
  render::Material rough;
  rough.shininess = 0.0f;
  EXPECT_DOUBLE_EQ(roughnessOf(rough), 1.0);
}

TEST(TruthView, BadMaterialsNameTheFileAndKey) {
  OrganAssets organ = patch();
  organ.material.layers[0].sigmaS.y = std::nanf("");
  auto r = truthMaterialOf(organ);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("patch_test.json"), std::string::npos) << r.error().message;
  EXPECT_NE(r.error().message.find("layers[0].sigma_s"), std::string::npos) << r.error().message;
  EXPECT_EQ(r.error().message.find('\n'), std::string::npos);

  organ = patch();
  organ.material.layers[0].sigmaT.x = 1.0f;  // below sigma_s: no absorption left
  r = truthMaterialOf(organ);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("layers[0].sigma_t"), std::string::npos) << r.error().message;

  // A layer depth outside the mesh: a map whose deepest boundary (1.0 * 3 mm) is below the
  // 4 mm thick patch's middle.
  organ = patch();
  organ.material.depthScaleMm = 3.0f;
  organ.material.layers.assign(5, organ.material.layers[0]);
  Image8 map(2, 2, 4);
  for (std::size_t i = 0; i < map.pixels.size(); ++i)
    map.pixels[i] = std::uint8_t(60 * (i % 4 + 1) + 15);  // boundaries increase through R, G, B, A
  organ.subsurfaceMap = map;
  r = truthMaterialOf(organ);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("depth_scale_mm"), std::string::npos) << r.error().message;
  EXPECT_NE(r.error().message.find("patch_test.json"), std::string::npos);
  organ.material.depthScaleMm = 1.0f;  // 1 mm deep at most: inside
  r = truthMaterialOf(organ);
  EXPECT_TRUE(r.ok()) << r.error().message;
  if (r.ok()) {
    EXPECT_EQ(r->layers.size(), 5u);
    EXPECT_EQ(r->maps.mapCount, 1);
  }

  auto wrong = renderTruth(organ, std::span<const Float3>(organ.mesh.positions).first(3), frame(), small());
  ASSERT_FALSE(wrong.ok());
  EXPECT_NE(wrong.error().message.find("render vertices"), std::string::npos);
}

}  // namespace
}  // namespace tissue::scene
