// The render pipeline's ray-march method (shaders/raymarch/) against its CPU model
// (tissue::subsurface, plane mode) in linear radiance, against the flat-slab closed form,
// golden images, a local poke on the data patch, and beside the other methods in one frame.
#include <algorithm>
#include <cstdio>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "gl_test_support.h"
#include "image_compare.h"
#include "test_scene.h"
#include "tissue/mesh/deformable_surface.h"
#include "tissue/mesh/load_mesh.h"
#include "tissue/mesh/vertex_normals.h"
#include "tissue/optics/schlick_phase.h"
#include "tissue/render/renderer.h"
#include "tissue/scene/material_file.h"
#include "tissue/subsurface/flat_slab.h"
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
  subsurface::PinholeCamera pinhole() const {
    return {camera.eye, camera.target, camera.up, camera.verticalFovDeg};
  }
};

PatchScene loadPatch() {
  PatchScene p;
  const std::filesystem::path data = TISSUE_TEST_DATA_DIR;
  auto file = scene::readMaterialFile(data / "materials" / "patch.json");
  EXPECT_TRUE(file) << file.error().message;
  p.map = *readImage(file->textures.subsurface, 4);
  auto stack = scene::layerStack(*file, p.map);
  EXPECT_TRUE(stack) << stack.error().message;
  p.stack = *stack;
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

// The patch on a renderer: one ray-march object, the CPU model's point lights as the scene's.
struct PatchGpu {
  render::Renderer renderer;
  render::MeshHandle mesh;
  render::Scene scene;
  render::RayMarchSettings& settings() { return std::get<render::RayMarchSettings>(scene.objects[0].method); }
  Result<void> upload(const mesh::DeformableSurface& s, std::span<const Float4> planes) {
    return renderer.updateMesh(mesh, {0, s.positions(), s.normals(), s.tangents(), planes});
  }
};

Result<PatchGpu> makeGpu(const PatchScene& p, context::GlContext& context) {
  auto r = render::Renderer::create(context.procAddressFunction());
  if (!r) return r.error();
  const auto& s = *p.surface;
  auto mesh = r->createMesh({s.positions(), s.normals(), s.tangents(), s.uvs(), s.triangles(), s.planes()});
  if (!mesh) return mesh.error();
  auto map = r->createTexture(p.map, render::TextureEncoding::LinearData);
  if (!map) return map.error();
  render::RayMarchSettings m;
  for (const auto& l : p.stack.layers)
    m.layers.push_back({l.sigma_s, l.sigma_t, float(optics::schlickKFromG(l.g))});
  m.subsurfaceMaps = {*map};
  m.depthScaleMm = p.stack.depthScaleMm;
  m.uvPerMm = p.uvPerMm;
  m.samples = 32;
  m.radianceScale = 8.0f;
  PatchGpu out{std::move(*r), *mesh, {}};
  out.scene.camera = p.camera;
  out.scene.lights.clear();
  for (const auto& l : p.lights) {
    render::Light light;
    light.positionMm = l.positionMm;
    light.color = l.radiance;
    light.intensity = 1.0f;
    out.scene.lights.push_back(light);
  }
  render::SceneObject organ;
  organ.mesh = *mesh;
  organ.method = m;
  out.scene.objects = {organ};
  return out;
}

// The last frame's linear radiance divided by `scale`, and where it is covered.
struct Radiance {
  std::vector<Float3> rgb;
  std::vector<std::uint8_t> covered;
};

Radiance readRadiance(render::Renderer& r, float scale) {
  Radiance out;
  auto frame = r.readFrame(render::FrameView::Radiance);
  EXPECT_TRUE(frame) << frame.error().message;
  if (!frame) return out;
  for (const Float4& p : frame->pixels) {
    out.rgb.push_back({p.x / scale, p.y / scale, p.z / scale});
    out.covered.push_back(p.w > 0.0f ? 1 : 0);
  }
  return out;
}

class RayMarchTest : public ::testing::TestWithParam<Backend> {};

TEST_P(RayMarchTest, ShaderMatchesItsCpuModelInLinearRadianceAndTheGolden) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  const PatchScene p = loadPatch();
  auto gpu = makeGpu(p, *context);
  ASSERT_TRUE(gpu) << gpu.error().message;
  auto image = gpu->renderer.renderImage(gpu->scene, kWidth, kHeight);
  ASSERT_TRUE(image) << image.error().message;
  ASSERT_NE(gpu->renderer.lastTimings().find("ray-march"), nullptr) << "the method's pass is named";
  const render::RayMarchSettings& s = gpu->settings();
  const Radiance g = readRadiance(gpu->renderer, s.radianceScale);
  subsurface::CpuImageSettings c;
  c.width = kWidth;
  c.height = kHeight;
  c.entry = subsurface::EntryMode::Planes;
  c.march.samples = s.samples;
  const subsurface::RadianceImage cpu =
      subsurface::renderSingleScatteringCpu(p.view(), p.stack, p.lights, p.pinhole(), c);
  // Same model, same jitter: float rounding, the RGBA16F target (2^-11 relative) and pixels whose
  // samples straddle a layer boundary differ. Compared where both cover (not silhouettes).
  std::vector<std::uint8_t> both(cpu.covered.size());
  std::size_t n = 0;
  for (std::size_t i = 0; i < both.size(); ++i)
    n += both[i] = cpu.covered[i] && g.covered[i];
  ASSERT_GT(n, both.size() / 2);
  const double rms = subsurface::relativeRadianceRms(g.rgb, cpu.radiance, both);
  // Per pixel: most agree to float and RGBA16F rounding (median 4e-4 on llvmpipe); under 1% of
  // pixels differ by up to tens of percent and dominate the RMS (1.2e-2) - presumably samples
  // that land on the other side of a layer boundary, as the GPU sampler's bilinear weights and
  // float arithmetic differ from the CPU model's double precision.
  std::vector<double> relative;
  for (std::size_t i = 0; i < both.size(); ++i) {
    if (!both[i]) continue;
    const Float3 a = g.rgb[i], b = cpu.radiance[i];
    relative.push_back(double(std::abs(a.x - b.x) + std::abs(a.y - b.y) + std::abs(a.z - b.z)) /
                       std::max(double(b.x + b.y + b.z), 1e-6));
  }
  std::sort(relative.begin(), relative.end());
  const double median = relative[relative.size() / 2], p99 = relative[relative.size() * 99 / 100];
  std::printf("[ model ] GPU vs CPU over %zu pixels: relative radiance rms %.5f, median %.5f, p99 %.5f\n", n,
              rms, median, p99);
  EXPECT_LT(rms, 0.02) << "GPU and CPU ray march disagree";
  EXPECT_LT(median, 2e-3) << "the typical pixel must agree to float and RGBA16F precision";
  EXPECT_LT(p99, 0.02) << "all but 1% of pixels must agree within 2%";
  EXPECT_GT(rms, 0.0) << "different arithmetic cannot agree to the bit: the comparison is not comparing";
  const std::string failure = checkGolden(std::string("raymarch_patch_") + backendName(GetParam()), *image);
  EXPECT_TRUE(failure.empty()) << failure;
}

// A flat quad at z = 0 (planes (0, 0, 1, 0)) with a constant subsurface map and a directional
// light: the local-plane estimate is exact, so each pixel must equal the closed form of
// subsurface::flatSlabSingleScattering for its own view direction.
TEST_P(RayMarchTest, FlatSlabUnderADirectionalLightMatchesTheClosedForm) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  SphereMesh quad = makePatch(400.0f, 2, 0.0f);
  const std::vector<Float4> planes(quad.positions.size(), Float4{0.0f, 0.0f, 1.0f, 0.0f});
  render::MeshArrays arrays = quad.arrays();
  arrays.planes = planes;
  auto mesh = renderer->createMesh(arrays);
  ASSERT_TRUE(mesh) << mesh.error().message;
  Image8 map(4, 4, 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x)
      for (int c = 0; c < 4; ++c)
        map.at(x, y)[c] = std::uint8_t(51 * (c + 1));  // boundaries 0.2 .. 0.8 of the scale
  auto texture = renderer->createTexture(map, render::TextureEncoding::LinearData);
  ASSERT_TRUE(texture);
  const float scaleMm = 2.0f, bounds[] = {0.4f, 0.8f, 1.2f, 1.6f};
  const std::vector<subsurface::LayerCoefficients> organ(5, {{1.0f, 1.0f, 2.0f}, {1.5f, 1.5f, 2.5f}, 0.8f});
  const std::vector<subsurface::LayerCoefficients> five = {
      {{2.0f, 1.0f, 1.0f}, {2.6f, 1.6f, 1.6f}, 0.25f},
      {{3.7f, 4.4f, 5.05f}, {3.732f, 4.57f, 5.53f}, 0.0f},
      {{6.0f, 3.0f, 2.0f}, {6.6f, 3.6f, 2.6f}, 0.4f},
      {{0.5f, 0.5f, 0.5f}, {1.0f, 1.2f, 1.4f}, -0.3f},
      {{1.0f, 1.0f, 2.0f}, {1.5f, 1.5f, 2.5f}, 0.8f}};
  render::Scene scene;
  scene.camera.eye = {10.0f, -50.0f, 120.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.camera.verticalFovDeg = 30.0f;
  scene.camera.nearMm = 20.0f;
  scene.camera.farMm = 500.0f;
  const glm::vec3 toLight = glm::normalize(glm::vec3(-0.5f, 0.3f, 1.0f));
  render::Light sun;
  sun.type = render::LightType::Directional;
  sun.direction = {-toLight.x, -toLight.y, -toLight.z};  // the way the light travels
  sun.color = {1.0f, 1.0f, 1.0f};
  sun.intensity = 1.0f;
  scene.lights = {sun};
  // (stack, samples, tolerance): one homogeneous medium converges as 1/n^2 (midpoint rule; 32
  // samples give about 1e-2, 128 about 1.5e-3, then float and RGBA16F rounding); layer
  // boundaries between samples make the five-layer error first order, ~ step / layer (the
  // CPU test needs 2000 samples for 3e-3; the shader allows at most 256).
  struct Case {
    const char* name;
    const std::vector<subsurface::LayerCoefficients>* layers;
    int samples;
    double tolerance;
  };
  for (const Case& k : {Case{"homogeneous", &organ, 128, 3e-3}, Case{"five-layer", &five, 256, 2e-2}}) {
    render::RayMarchSettings s;
    for (const auto& l : *k.layers)
      s.layers.push_back({l.sigma_s, l.sigma_t, float(optics::schlickKFromG(l.g))});
    s.subsurfaceMaps = {*texture};
    s.depthScaleMm = scaleMm;
    s.uvPerMm = 1.0f / 400.0f;
    s.samples = k.samples;
    s.depthMaxMm = 2.5f;
    s.attenuationThreshold = 0.0f;
    s.jitter = false;
    s.radianceScale = 1.0f;
    render::SceneObject o;
    o.mesh = *mesh;
    o.method = s;
    scene.objects = {o};
    ASSERT_TRUE(renderer->renderImage(scene, 64, 48));
    auto radiance = renderer->readFrame(render::FrameView::Radiance);
    auto position = renderer->readFrame(render::FrameView::Position);
    ASSERT_TRUE(radiance && position);
    double worst = 0.0;
    for (std::size_t i = 0; i < radiance->pixels.size(); ++i) {
      const Float4 P = position->pixels[i], L = radiance->pixels[i];
      ASSERT_GT(L.w, 0.0f) << "the quad fills the image";
      const glm::vec3 toEye = glm::normalize(glm::vec3(10.0f, -50.0f, 120.0f) - glm::vec3(P.x, P.y, P.z));
      const Float3 exact = subsurface::flatSlabSingleScattering(
          *k.layers, k.layers == &five ? std::span<const float>(bounds) : std::span<const float>(),
          {toEye.x, toEye.y, toEye.z}, {toLight.x, toLight.y, toLight.z}, s.depthMaxMm);
      worst = std::max({worst, std::abs(double(L.x - exact.x)) / double(exact.x),
                        std::abs(double(L.y - exact.y)) / double(exact.y),
                        std::abs(double(L.z - exact.z)) / double(exact.z)});
    }
    std::printf("[ slab ] %s, %d samples: largest relative error %.5f\n", k.name, k.samples, worst);
    EXPECT_LT(worst, k.tolerance);
  }
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

// Largest RGB difference per pixel of two radiance frames.
std::vector<float> pixelDifferences(const Radiance& a, const Radiance& b) {
  std::vector<float> out(a.rgb.size());
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = std::max({std::abs(a.rgb[i].x - b.rgb[i].x), std::abs(a.rgb[i].y - b.rgb[i].y),
                       std::abs(a.rgb[i].z - b.rgb[i].z), a.covered[i] != b.covered[i] ? 1.0f : 0.0f});
  return out;
}

TEST_P(RayMarchTest, APokeChangesTheImageOnlyAroundItAndMatchesAFullRefit) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  PatchScene p = loadPatch();
  auto gpu = makeGpu(p, *context);
  ASSERT_TRUE(gpu) << gpu.error().message;
  ASSERT_TRUE(gpu->renderer.renderImage(gpu->scene, kWidth, kHeight));
  const Radiance before = readRadiance(gpu->renderer, 1.0f);
  const std::vector<Float4> restPlanes(p.surface->planes().begin(), p.surface->planes().end());
  // Step 1: poke 3 mm deep over a radius of 8 mm; only the poked planes are re-fitted.
  constexpr float kRadiusMm = 8.0f;
  poke(p, kRadiusMm, 3.0f);
  ASSERT_TRUE(gpu->upload(*p.surface, p.surface->planes()));
  ASSERT_TRUE(gpu->renderer.renderImage(gpu->scene, kWidth, kHeight));
  const Radiance after = readRadiance(gpu->renderer, 1.0f);
  // Step 2: every changed pixel lies near the poke. Reach: the poke radius, plus the plane
  // sphere (r = -ln(0.01) / 1.6 = 2.9 mm), plus how far a march and its light paths reach
  // sideways (a few mm), plus the poke depth: 16 mm around the site, projected.
  const render::Camera& cam = p.camera;
  const glm::mat4 vp =
      glm::perspective(glm::radians(cam.verticalFovDeg), float(kWidth) / kHeight, cam.nearMm, cam.farMm) *
      glm::lookAt(glm::vec3(cam.eye.x, cam.eye.y, cam.eye.z),
                  glm::vec3(cam.target.x, cam.target.y, cam.target.z),
                  glm::vec3(cam.up.x, cam.up.y, cam.up.z));
  const Float3 c = p.surface->geometricRestPositions()[p.site];
  const glm::vec4 clip = vp * glm::vec4(c.x, c.y, c.z, 1.0f);
  const glm::vec2 centre((clip.x / clip.w * 0.5f + 0.5f) * kWidth, (0.5f - clip.y / clip.w * 0.5f) * kHeight);
  const float reachPx = 16.0f / (clip.w * std::tan(glm::radians(cam.verticalFovDeg) * 0.5f)) * kHeight * 0.5f;
  // A change: more than the RGBA16F target's rounding of radiances around 1 (2^-11).
  constexpr float kChanged = 2e-3f;
  const std::vector<float> diff = pixelDifferences(after, before);
  int changed = 0, outside = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      if (diff[std::size_t(y) * kWidth + x] <= kChanged) continue;
      ++changed;
      // The oblique view squeezes the region vertically: a circle of the full radius contains it.
      if (glm::distance(glm::vec2(x + 0.5f, y + 0.5f), centre) > reachPx) ++outside;
    }
  std::printf("[ poke ] %d of %d pixels changed, all within %.1f px of the site\n", changed, kWidth * kHeight,
              double(reachPx));
  EXPECT_GT(changed, 100) << "the poke must show";
  EXPECT_EQ(outside, 0) << "pixels changed farther than 16 mm from the poke (reach " << reachPx << " px)";
  // Step 3: planes re-fitted from scratch give the same radiance, bit for bit.
  p.surface->refitAllPlanes();
  ASSERT_TRUE(gpu->upload(*p.surface, p.surface->planes()));
  ASSERT_TRUE(gpu->renderer.renderImage(gpu->scene, kWidth, kHeight));
  const Radiance refit = readRadiance(gpu->renderer, 1.0f);
  const std::vector<float> refitDiff = pixelDifferences(refit, after);
  EXPECT_EQ(*std::max_element(refitDiff.begin(), refitDiff.end()), 0.0f);
  // Step 4: the planes matter: keeping the rest planes on the poked mesh gives another image.
  ASSERT_TRUE(gpu->upload(*p.surface, restPlanes));
  ASSERT_TRUE(gpu->renderer.renderImage(gpu->scene, kWidth, kHeight));
  const std::vector<float> staleDiff = pixelDifferences(readRadiance(gpu->renderer, 1.0f), after);
  EXPECT_GT(*std::max_element(staleDiff.begin(), staleDiff.end()), 0.02f);
}

// Lit, separable and ray-march objects in one frame: every method's pass runs, and the
// ray-marched object's radiance is what it is alone (the methods share the targets, not state).
TEST_P(RayMarchTest, CoexistsWithLitAndSeparableObjectsInOneFrame) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  const PatchScene p = loadPatch();
  auto gpu = makeGpu(p, *context);
  ASSERT_TRUE(gpu) << gpu.error().message;
  gpu->scene.camera.eye = {0.0f, -90.0f, 110.0f};  // wide enough for all three
  ASSERT_TRUE(gpu->renderer.renderImage(gpu->scene, kWidth, kHeight));
  const Radiance alone = readRadiance(gpu->renderer, 1.0f);
  // Two small patches beside the organ patch (80 x 60 mm), at x = -/+ 60 mm: Lit and Separable.
  SphereMesh left = makePatch(20.0f, 2, 0.0f), right = left;
  for (auto& q : left.positions)
    q.x -= 60.0f;
  for (auto& q : right.positions)
    q.x += 60.0f;
  auto a = gpu->renderer.createMesh(left.arrays());
  auto b = gpu->renderer.createMesh(right.arrays());
  ASSERT_TRUE(a && b);
  render::SceneObject lit, separable;
  lit.mesh = *a;
  separable.mesh = *b;
  separable.method = render::rankOneSeparable({{1.0f, 1.0f, 1.0f, 0.0f}});
  gpu->scene.objects.push_back(lit);
  gpu->scene.objects.push_back(separable);
  auto image = gpu->renderer.renderImage(gpu->scene, kWidth, kHeight);
  ASSERT_TRUE(image) << image.error().message;
  for (const char* pass : {"lit", "separable:geometry", "ray-march", "separable:blur-x", "tonemap"})
    EXPECT_NE(gpu->renderer.lastTimings().find(pass), nullptr) << pass;
  const Radiance mixed = readRadiance(gpu->renderer, 1.0f);
  int same = 0, organ = 0, others = 0;
  for (std::size_t i = 0; i < mixed.rgb.size(); ++i) {
    if (alone.covered[i]) {
      ++organ;
      same += mixed.rgb[i].x == alone.rgb[i].x && mixed.rgb[i].y == alone.rgb[i].y &&
              mixed.rgb[i].z == alone.rgb[i].z;
    } else {
      others += mixed.covered[i];
    }
  }
  EXPECT_GT(organ, 500);
  EXPECT_EQ(same, organ) << "the ray-marched object changed when other methods joined the frame";
  EXPECT_GT(others, 50) << "the lit and separable objects are drawn";
}

TEST_P(RayMarchTest, BadSettingsAreClearErrors) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  const PatchScene p = loadPatch();
  auto gpu = makeGpu(p, *context);
  ASSERT_TRUE(gpu) << gpu.error().message;
  auto expectError = [&](const char* what) {
    auto image = gpu->renderer.renderImage(gpu->scene, 32, 32);
    ASSERT_FALSE(image) << what;
    EXPECT_NE(image.error().message.find(what), std::string::npos) << image.error().message;
  };
  const render::RayMarchSettings good = gpu->settings();
  gpu->settings().layers.pop_back();
  expectError("4N + 1 layers");
  gpu->settings() = good;
  gpu->settings().subsurfaceMaps = {render::TextureHandle{999}};
  expectError("does not hold");
  gpu->settings() = good;
  gpu->settings().subsurfaceMaps = {render::TextureHandle{}};
  expectError("is no texture");
  gpu->settings() = good;
  gpu->settings().layers[2].sigma_t = {0.0f, 1.0f, 1.0f};
  expectError("sigma_t > 0");
  // A mesh without planes cannot be ray marched.
  const auto& s = *p.surface;
  auto bare =
      gpu->renderer.createMesh({s.positions(), s.normals(), s.tangents(), s.uvs(), s.triangles(), {}});
  ASSERT_TRUE(bare);
  gpu->settings() = good;
  gpu->scene.objects[0].mesh = *bare;
  expectError("no planes");
}

INSTANTIATE_TEST_SUITE_P(Backends, RayMarchTest, ::testing::Values(Backend::Egl, Backend::OsMesa),
                         backendParamName);

}  // namespace
}  // namespace tissue::test
