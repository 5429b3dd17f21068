// Texture-space diffusion's own model on llvmpipe, through the render pipeline's maps
// (Renderer::readTextureSpaceMaps): energy of a uniformly lit patch texel by texel, the stretch
// map of a rest and a stretched patch, the depth-based size and the culled and clipped maps on
// known geometry. (The method's golden and optimisation tolerances are in
// texture_space_pipeline_test.cpp.)
#include <cmath>
#include <numbers>

#include "gl_test_support.h"
#include "image_compare.h"
#include "test_scene.h"

namespace tissue::test {
namespace {

constexpr int kMapSize = 512;

/// Texels per mm of a UV map at `size` texels.
float texelsPerMm(const SphereMesh& m, int size) {
  return render::uvDensity(m.positions, m.uvs, m.triangles) * float(size);
}

// A renderer drawing one mesh with texture-space diffusion, returning its maps.
class TextureSpaceMapsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto context = createContext(Backend::Egl);
    if (!context) GTEST_FAIL() << "egl context unavailable: " << context.error().message;
    m_context = std::move(*context);
    auto r = render::Renderer::create(m_context->procAddressFunction());
    ASSERT_TRUE(r) << r.error().message;
    m_renderer = std::make_unique<render::Renderer>(std::move(*r));
  }
  void setMesh(const SphereMesh& mesh) {
    auto handle = m_renderer->createMesh(mesh.arrays());
    ASSERT_TRUE(handle) << handle.error().message;
    m_mesh = *handle;
  }
  Result<render::TextureSpaceMaps> renderMaps(render::Scene scene, int width, int height,
                                              const render::TextureSpaceSettings& settings) {
    render::SceneObject object;
    object.mesh = m_mesh;
    object.method = settings;
    object.material = scene.material;
    scene.objects = {object};
    if (auto image = m_renderer->renderImage(scene, width, height); !image) return image.error();
    return m_renderer->readTextureSpaceMaps();
  }
  std::unique_ptr<context::GlContext> m_context;
  std::unique_ptr<render::Renderer> m_renderer;
  render::MeshHandle m_mesh;
};

TEST_F(TextureSpaceMapsTest, UniformlyLitPatchKeepsItsMeanBrightness) {
  setMesh(makeInsetPatch(40, 60.0f, 60.0f));
  render::Scene scene = goldenScene();
  scene.camera.eye = {0.0f, 0.0f, 150.0f};
  scene.lights[0].positionMm = {0.0f, 0.0f, 1e6f};  // N.L = 1 everywhere: uniform irradiance
  auto maps = renderMaps(scene, 64, 64, skinTextureSpace(kMapSize, false));
  ASSERT_TRUE(maps) << maps.error().message;
  double e = 0.0, m = 0.0, worst = 0.0;
  int covered = 0;
  for (std::size_t t = 0; t < maps->diffused.pixels.size(); ++t) {
    if (maps->irradiance.pixels[t].w <= 0.0f) continue;
    const Float4 in = maps->irradiance.pixels[t], out = maps->diffused.pixels[t];
    e += double(in.x), m += double(out.x), ++covered;
    worst = std::max(worst, std::abs(double(out.x) / double(in.x) - 1.0));
  }
  ASSERT_GT(covered, kMapSize * kMapSize / 2);
  EXPECT_NEAR(m / e, 1.0, 0.005);  // the profile's weights sum to 1 per channel
  EXPECT_LT(worst, 0.01);          // also at the patch's border (normalised convolution)
}

TEST_F(TextureSpaceMapsTest, StretchMapMatchesRestAndStretchedPatch) {
  for (float stretchX : {1.0f, 1.5f}) {
    const SphereMesh patch = makeInsetPatch(10, 40.0f, 20.0f, stretchX);
    setMesh(patch);
    auto maps = renderMaps(goldenScene(), 32, 32, skinTextureSpace(kMapSize, false));
    ASSERT_TRUE(maps) << maps.error().message;
    // mm per UV unit: the 40 x 20 mm patch spans 0.96 of the map each way.
    const double expectU = 40.0 * double(stretchX) / 0.96, expectV = 20.0 / 0.96;
    int checked = 0;
    for (std::size_t t = 0; t < maps->stretch.pixels.size(); ++t) {
      if (maps->irradiance.pixels[t].w <= 0.0f) continue;
      EXPECT_NEAR(maps->stretch.pixels[t].x, expectU, expectU * 2e-3) << t;
      EXPECT_NEAR(maps->stretch.pixels[t].y, expectV, expectV * 2e-3) << t;
      if (++checked > 2000) break;
    }
    EXPECT_GT(checked, 1000);
  }
}

TEST_F(TextureSpaceMapsTest, DepthSizeCullAndClipOnKnownGeometry) {
  const SphereMesh sphere = makeSphere(40.0f, 48, 96);
  const float density = texelsPerMm(sphere, kMapSize);
  setMesh(sphere);
  render::Scene scene = goldenScene();
  scene.camera.eye = {0.0f, 0.0f, 400.0f};
  scene.camera.farMm = 1000.0f;
  // Depth-based size: eq. 3-4 with d to the nearest corner of [-40, 40]^3 from (0, 0, 400).
  render::TextureSpaceSettings s = skinTextureSpace(kMapSize, false);
  s.depthSize = true;
  auto maps = renderMaps(scene, 200, 200, s);
  ASSERT_TRUE(maps) << maps.error().message;
  // d_ref: one texel of the full map per pixel, H / (2 tan(fov / 2) texelsPerMm).
  const float dRef = 200.0f / (2.0f * std::tan(20.0f * std::numbers::pi_v<float> / 180.0f) * density);
  const float d = std::sqrt(360.0f * 360.0f + 2.0f * 40.0f * 40.0f);
  EXPECT_EQ(maps->size, render::irradianceMapSize(render::irradianceMapScale(d, dRef), kMapSize));
  EXPECT_LT(maps->size, kMapSize);
  // Culled: the area within 105 degrees of the view direction, (1 + cos 75 deg... ) = (1 + 0.2588) / 2
  // of a sphere seen from far; from 10 radii a little less.
  s = skinTextureSpace(kMapSize, false);
  s.cull = true;
  maps = renderMaps(scene, 200, 200, s);
  ASSERT_TRUE(maps) << maps.error().message;
  double visible = 0.0, drawn = 0.0;
  for (std::size_t t = 0; t < maps->irradiance.pixels.size(); ++t) {
    if (maps->position.pixels[t].w <= 0.0f) continue;
    drawn += 1.0;
    visible += maps->irradiance.pixels[t].w > 0.0f ? 1.0 : 0.0;
  }
  // Texels are not equal-area on a UV sphere: weight by the known latitude instead is overkill;
  // the sphere's seen hemisphere plus 15 degrees is between a half and (1 + 0.2588) / 2.
  EXPECT_GT(visible / drawn, 0.5);
  EXPECT_LT(visible / drawn, 0.70);
  // Clipped: a camera close to the sphere's +x side sees only part of it. Positions come from
  // the unclipped map (clipped texels are not drawn at all).
  scene.camera.eye = {60.0f, 0.0f, 60.0f};
  scene.camera.target = {60.0f, 0.0f, 0.0f};
  scene.camera.nearMm = 1.0f;
  auto positions = renderMaps(scene, 200, 200, skinTextureSpace(kMapSize, false));
  ASSERT_TRUE(positions) << positions.error().message;
  s = skinTextureSpace(kMapSize, false);
  s.clip = true;
  maps = renderMaps(scene, 200, 200, s);
  ASSERT_TRUE(maps) << maps.error().message;
  int kept = 0, wrong = 0, total = 0;
  const float tanHalf = std::tan(20.0f * std::numbers::pi_v<float> / 180.0f);
  for (std::size_t t = 0; t < maps->irradiance.pixels.size(); ++t) {
    const Float4 p = positions->position.pixels[t];
    if (p.w <= 0.0f) continue;
    ++total;
    // Eye space of this camera: x = p.x - 60, y = p.y, z = p.z - 60 (looking down -z).
    const float z = 60.0f - p.z;
    const bool inside =
        z > 1.0f && std::abs(p.x - 60.0f) <= z * tanHalf * 0.98f && std::abs(p.y) <= z * tanHalf * 0.98f;
    const bool outside =
        z < 0.9f || std::abs(p.x - 60.0f) >= z * tanHalf * 1.02f || std::abs(p.y) >= z * tanHalf * 1.02f;
    const bool keptHere = maps->irradiance.pixels[t].w > 0.0f;
    kept += keptHere;
    wrong += (inside && !keptHere) || (outside && keptHere);
  }
  EXPECT_GT(total, 1000);
  EXPECT_LT(kept, total / 2);  // most of the sphere is off screen
  EXPECT_GT(kept, 0);
  EXPECT_LT(wrong, total / 200);
}

}  // namespace
}  // namespace tissue::test
