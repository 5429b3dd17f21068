// The truth's camera against the renderer's projection (scene/truth_view.h): the liver drawn Lit
// by the scene, its Position view read back, and the truth's centre ray of every pixel traced
// through truthCameraOf(scene.camera()): coverage agrees pixel by pixel (but for silhouette
// pixels whose centre grazes the mesh) and the hit points match the rasterised positions. Then
// renderTruth(Scene&) covers the same pixels. Needs GL: fails, never skips, without a context.
#include <gtest/gtest.h>

#include <cmath>

#include "tissue/scene/scene.h"
#include "tissue/scene/truth_view.h"

namespace tissue::scene {
namespace {

const std::filesystem::path kData = TISSUE_TEST_DATA_DIR;

TEST(TruthViewGl, CameraMatchesTheRenderersProjectionPixelByPixel) {
  SceneSettings settings;
  settings.materials.textureRoots = {TISSUE_TEST_GENERATED_DATA_DIR, TISSUE_TEST_DATA_DIR};
  auto scene = Scene::create({}, settings);
  ASSERT_TRUE(scene.ok()) << "no headless context: " << scene.error().message;
  OrganDesc desc;
  desc.mesh = kData / "meshes" / "liver.obj";
  desc.material = kData / "materials" / "liver.json";
  auto id = scene->addOrgan(desc);
  ASSERT_TRUE(id.ok()) << id.error().message;
  const int w = 96, h = 72;
  auto image = scene->renderImage(w, h);
  ASSERT_TRUE(image.ok()) << image.error().message;
  auto position = scene->renderer().readFrame(render::FrameView::Position);
  ASSERT_TRUE(position.ok()) << position.error().message;

  const OrganAssets& organ = scene->assets(*id);
  auto rays = truth::makeRayMesh(organ.mesh.positions, organ.mesh.triangles);
  ASSERT_TRUE(rays.ok()) << rays.error().message;
  const truth::TruthCamera camera = truthCameraOf(scene->camera());
  int both = 0, onlyGl = 0, onlyTruth = 0, far = 0;
  std::vector<std::uint8_t> truthCovered(std::size_t(w) * h, 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Float3 d = truth::pinholeRayDirection(camera, w, h, x + 0.5, y + 0.5);
      const auto hit =
          (*rays)->intersect({camera.eye.x, camera.eye.y, camera.eye.z}, {d.x, d.y, d.z}, 0.0, 1e30);
      const Float4 p = position->at(x, y);
      const bool gl = p.w > 0.0f;
      truthCovered[std::size_t(y) * w + x] = hit ? 1 : 0;
      if (gl && hit) {
        ++both;
        const Float3 q = camera.eye + float(hit->t) * d;
        if (length(q - Float3{p.x, p.y, p.z}) > 0.05f) ++far;
      } else if (gl) {
        ++onlyGl;
      } else if (hit) {
        ++onlyTruth;
      }
    }
  std::printf("  covered by both %d, only GL %d, only the truth %d; hit points > 0.05 mm apart %d\n", both,
              onlyGl, onlyTruth, far);
  ASSERT_GT(both, 500);
  EXPECT_LE(onlyGl + onlyTruth, both / 100);  // silhouette pixels only
  EXPECT_LE(far, both / 100);

  // The Scene overload traces the same frame: the same pixels covered.
  truth::PathTraceSettings s;
  s.width = w;
  s.height = h;
  s.samplesPerPass = 1;
  s.passes = 2;
  s.threads = 2;
  s.maxInteractions = 200;
  auto traced = renderTruth(*scene, *id, s);
  ASSERT_TRUE(traced.ok()) << traced.error().message;
  EXPECT_EQ(traced->covered, truthCovered);
}

}  // namespace
}  // namespace tissue::scene
