// Ray-marched subsurface texture mapping on the GPU (shaders/raymarch/) against its CPU model
// (tissue::subsurface, plane mode), golden images, and a local poke on the data patch.
#include <cstdio>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "gl_test_support.h"
#include "image_compare.h"
#include "tissue/mesh/deformable_surface.h"
#include "tissue/mesh/load_mesh.h"
#include "tissue/mesh/vertex_normals.h"
#include "tissue/optics/schlick_phase.h"
#include "tissue/render/raymarch_renderer.h"
#include "tissue/subsurface/reference_image.h"

namespace tissue::test {
namespace {

constexpr int kWidth = 128, kHeight = 96;

// The data patch (80 x 60 mm, +z out) with its layer stack, seen obliquely from above.
struct PatchScene {
  std::unique_ptr<mesh::DeformableSurface> surface;
  subsurface::LayerStack stack;
  Image8 map;
  float uvPerMm = 0.0f;
  render::Camera camera;
  std::vector<subsurface::Light> lights;
  std::uint32_t site = 0;  // geometric vertex nearest the centre

  subsurface::MeshView view() const {
    const auto& s = *surface;
    return {s.positions(), s.normals(), s.tangents(), s.planes(), s.uvs(), s.triangles(), uvPerMm};
  }
  std::vector<render::RayMarchLight> gpuLights() const {
    std::vector<render::RayMarchLight> out;
    for (const auto& l : lights)
      out.push_back({l.positionMm, l.radiance});
    return out;
  }
};

PatchScene loadPatch() {
  PatchScene p;
  const std::filesystem::path data = TISSUE_TEST_DATA_DIR;
  auto stack = subsurface::loadLayerStack(data / "materials" / "patch.json", data);
  EXPECT_TRUE(stack) << stack.error().message;
  p.stack = *stack;
  p.map = *readImage(data / "textures" / "patch" / "subsurface.png", 4);
  auto m = mesh::loadMesh(data / "meshes" / "patch.obj", {.requireUvs = true});
  EXPECT_TRUE(m) << m.error().message;
  mesh::PlaneFitSettings planes;
  planes.sigma_t = 1.6f;  // smallest RGB extinction of the patch's outer layer
  auto surface = mesh::DeformableSurface::create(std::move(*m), planes, 2);
  EXPECT_TRUE(surface) << surface.error().message;
  p.surface = std::make_unique<mesh::DeformableSurface>(std::move(*surface));
  const auto& s = *p.surface;
  p.uvPerMm = subsurface::uvPerMmOf(s.positions(), s.uvs(), s.triangles());
  float best = 1e30f;
  const auto rest = s.geometricRestPositions();
  for (std::uint32_t i = 0; i < rest.size(); ++i) {
    const float d = rest[i].x * rest[i].x + rest[i].y * rest[i].y;
    if (d < best) best = d, p.site = i;
  }
  p.camera.eye = {0.0f, -45.0f, 55.0f};
  p.camera.target = {0.0f, 0.0f, 3.0f};
  p.camera.verticalFovDeg = 45.0f;
  p.camera.nearMm = 10.0f;
  p.camera.farMm = 300.0f;
  p.lights = {{{40.0f, -60.0f, 120.0f}, {2.2f, 2.1f, 2.0f}}, {{-80.0f, 40.0f, 30.0f}, {1.2f, 1.1f, 1.0f}}};
  return p;
}

Result<render::RayMarchRenderer> makeRenderer(const PatchScene& p, context::GlContext& context) {
  auto r = render::RayMarchRenderer::create(context.procAddressFunction());
  if (!r) return r.error();
  const auto& s = *p.surface;
  if (auto ok =
          r->setMesh({s.positions(), s.normals(), s.tangents(), s.uvs(), s.triangles(), {}}, s.planes());
      !ok)
    return ok.error();
  render::RayMarchMaterial m;
  for (const auto& l : p.stack.layers)
    m.layers.push_back({l.sigma_s, l.sigma_t, float(optics::schlickKFromG(l.g))});
  m.subsurfaceMaps = {p.map};
  m.depthScaleMm = p.stack.depthScaleMm;
  m.uvPerMm = p.uvPerMm;
  if (auto ok = r->setMaterial(m); !ok) return ok.error();
  return r;
}

render::RayMarchRenderSettings testSettings() {
  render::RayMarchRenderSettings s;
  s.samples = 32;
  return s;
}

class RayMarchTest : public ::testing::TestWithParam<Backend> {};

TEST_P(RayMarchTest, ShaderMatchesItsCpuModelAndTheGolden) {
  TISSUE_CONTEXT_OR_SKIP(context, GetParam());
  const PatchScene p = loadPatch();
  auto renderer = makeRenderer(p, *context);
  ASSERT_TRUE(renderer) << renderer.error().message;
  const render::RayMarchRenderSettings s = testSettings();
  const auto lights = p.gpuLights();
  auto gpu = renderer->renderImage(p.camera, lights, s, kWidth, kHeight);
  ASSERT_TRUE(gpu) << gpu.error().message;
  subsurface::CpuImageSettings c;
  c.width = kWidth;
  c.height = kHeight;
  c.entry = subsurface::EntryMode::Planes;
  c.march.samples = s.samples;
  const subsurface::RadianceImage cpu = subsurface::renderSingleScatteringCpu(
      p.view(), p.stack, p.lights, {p.camera.eye, p.camera.target, p.camera.up, p.camera.verticalFovDeg}, c);
  const Image8 cpuImage = subsurface::toDisplay(cpu, s.exposure, s.background);
  // Same model, same jitter: only float rounding and rasterisation at silhouettes differ.
  const double rms = subsurface::displayRms(*gpu, cpuImage, cpu.covered);
  std::printf("[ model ] GPU vs CPU rms %.5f\n", rms);
  EXPECT_LT(rms, 0.01) << "GPU and CPU ray march disagree";
  const ImageDiff d = compareImages(*gpu, cpuImage, 6);
  EXPECT_LT(d.fractionOver, 0.02);
  const std::string failure = checkGolden(std::string("raymarch_patch_") + backendName(GetParam()), *gpu);
  EXPECT_TRUE(failure.empty()) << failure;
}

// Pushes the geometric vertices within `radiusMm` of the site along -normal, up to `depthMm`
// at the site with a cosine falloff, and updates the surface (planes re-fitted incrementally).
void poke(PatchScene& p, float radiusMm, float depthMm) {
  const auto rest = p.surface->geometricRestPositions();
  std::vector<Float3> normals(rest.size()), positions(rest.begin(), rest.end());
  mesh::computeVertexNormals(rest, p.surface->geometricTriangles(), normals);
  const glm::vec3 site(rest[p.site].x, rest[p.site].y, rest[p.site].z);
  for (std::size_t i = 0; i < rest.size(); ++i) {
    const float d = glm::distance(glm::vec3(rest[i].x, rest[i].y, rest[i].z), site);
    if (d >= radiusMm) continue;
    const float w = depthMm * 0.5f * (1.0f + std::cos(3.14159265f * d / radiusMm));
    positions[i] = {rest[i].x - w * normals[i].x, rest[i].y - w * normals[i].y, rest[i].z - w * normals[i].z};
  }
  p.surface->update(positions);
}

Result<void> upload(render::RayMarchRenderer& r, const mesh::DeformableSurface& s,
                    std::span<const Float4> planes) {
  return r.updateMesh(s.positions(), s.normals(), s.tangents(), planes);
}

TEST_P(RayMarchTest, APokeChangesTheImageOnlyAroundItAndMatchesAFullRefit) {
  TISSUE_CONTEXT_OR_SKIP(context, GetParam());
  PatchScene p = loadPatch();
  auto renderer = makeRenderer(p, *context);
  ASSERT_TRUE(renderer) << renderer.error().message;
  const render::RayMarchRenderSettings s = testSettings();
  const auto lights = p.gpuLights();
  auto before = renderer->renderImage(p.camera, lights, s, kWidth, kHeight);
  ASSERT_TRUE(before) << before.error().message;
  const std::vector<Float4> restPlanes(p.surface->planes().begin(), p.surface->planes().end());
  // Step 1: poke 3 mm deep over a radius of 8 mm; only the poked planes are re-fitted.
  constexpr float kRadiusMm = 8.0f;
  poke(p, kRadiusMm, 3.0f);
  ASSERT_TRUE(upload(*renderer, *p.surface, p.surface->planes()));
  auto after = renderer->renderImage(p.camera, lights, s, kWidth, kHeight);
  ASSERT_TRUE(after) << after.error().message;
  // Step 2: every changed pixel lies near the poke. Reach: the poke radius, plus the plane
  // sphere (r = -ln(0.01) / 1.6 = 2.9 mm), plus how far a march and its light paths reach
  // sideways (a few mm), plus the poke depth: 16 mm around the site, projected.
  const glm::mat4 vp = glm::perspective(glm::radians(p.camera.verticalFovDeg), float(kWidth) / kHeight,
                                        p.camera.nearMm, p.camera.farMm) *
                       glm::lookAt(glm::vec3(p.camera.eye.x, p.camera.eye.y, p.camera.eye.z),
                                   glm::vec3(p.camera.target.x, p.camera.target.y, p.camera.target.z),
                                   glm::vec3(p.camera.up.x, p.camera.up.y, p.camera.up.z));
  const Float3 c = p.surface->geometricRestPositions()[p.site];
  const glm::vec4 clip = vp * glm::vec4(c.x, c.y, c.z, 1.0f);
  const glm::vec2 centre((clip.x / clip.w * 0.5f + 0.5f) * kWidth, (0.5f - clip.y / clip.w * 0.5f) * kHeight);
  const float reachPx =
      16.0f / (clip.w * std::tan(glm::radians(p.camera.verticalFovDeg) * 0.5f)) * kHeight * 0.5f;
  int changed = 0, outside = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      int diff = 0;
      for (int k = 0; k < 3; ++k)
        diff = std::max(diff, std::abs(after->at(x, y)[k] - before->at(x, y)[k]));
      if (diff <= 1) continue;
      ++changed;
      // The oblique view squeezes the region vertically: a circle of the full radius contains it.
      if (glm::distance(glm::vec2(x + 0.5f, y + 0.5f), centre) > reachPx) ++outside;
    }
  std::printf("[ poke ] %d of %d pixels changed, all within %.1f px of the site\n", changed, kWidth * kHeight,
              double(reachPx));
  EXPECT_GT(changed, 100) << "the poke must show";
  EXPECT_EQ(outside, 0) << "pixels changed farther than 16 mm from the poke (reach " << reachPx << " px)";
  // Step 3: planes re-fitted from scratch give the same image, bit for bit.
  p.surface->refitAllPlanes();
  ASSERT_TRUE(upload(*renderer, *p.surface, p.surface->planes()));
  auto refit = renderer->renderImage(p.camera, lights, s, kWidth, kHeight);
  ASSERT_TRUE(refit) << refit.error().message;
  EXPECT_EQ(compareImages(*refit, *after, 0).maxDiff, 0);
  // Step 4: the planes matter: keeping the rest planes on the poked mesh gives another image.
  ASSERT_TRUE(upload(*renderer, *p.surface, restPlanes));
  auto stale = renderer->renderImage(p.camera, lights, s, kWidth, kHeight);
  ASSERT_TRUE(stale) << stale.error().message;
  EXPECT_GT(compareImages(*stale, *after, 0).maxDiff, 2);
}

INSTANTIATE_TEST_SUITE_P(Backends, RayMarchTest, ::testing::Values(Backend::Egl, Backend::OsMesa),
                         backendParamName);

}  // namespace
}  // namespace tissue::test
