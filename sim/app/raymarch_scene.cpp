#include "raymarch_scene.h"
#include "gl_environment.h"

#include <algorithm>
#include <cmath>

#include "organ_data.h"
#include "output.h"
#include "tissue/context/headless_context.h"
#include "tissue/core/vec_math.h"
#include "tissue/mesh/load_mesh.h"
#include "tissue/mesh/vertex_normals.h"
#include "tissue/studies/deformations.h"
#include "tissue/subsurface/reference_image.h"

namespace tissue::sim_app {
namespace {

/// The layer stack of data/materials/<stem>.json with its subsurface map (scene::layerStack),
/// and the texture units per mm of `s`.
Result<materials::RayMarchMaterial> rayMarchMaterialFor(const mesh::DeformableSurface& s,
                                                        const std::string& stem) {
  auto file = readDataMaterial(dataDir() / "materials" / (stem + ".json"));
  if (!file) return Error{file.error().message + " (ray marching needs a data/ mesh with a material file)"};
  if (file->textures.subsurface.empty())
    return Error{file->file.string() + ": ray marching needs textures.subsurface (docs/DATA.md)"};
  materials::RayMarchMaterial m;
  auto map = readImage(file->textures.subsurface, 4);
  if (!map) return Error{"subsurface map " + file->textures.subsurface.string() + ": " + map.error().message};
  m.subsurfaceMap = std::move(*map);
  auto stack = scene::layerStack(*file, m.subsurfaceMap);
  if (!stack) return stack.error();
  m.stack = std::move(*stack);
  m.uvPerMm = subsurface::uvPerMmOf(s.positions(), s.uvs(), s.triangles());
  return m;
}

}  // namespace

Result<RayMarchScene> loadRayMarchScene(const std::filesystem::path& meshFile, float aspect, bool closeUp) {
  const std::string stem = meshFile.stem().string();
  auto material = readDataMaterial(dataDir() / "materials" / (stem + ".json"));
  if (!material)
    return Error{material.error().message + " (ray marching needs a data/ mesh with a material file)"};
  auto loaded = mesh::loadMesh(meshFile, {.requireUvs = true});
  if (!loaded) return loaded.error();
  // Plane neighbourhoods from the first layer's extinction (François eq. 8).
  mesh::PlaneFitSettings planes;
  planes.sigma_t = scene::firstLayerMinSigmaT(*material);
  auto surface = mesh::DeformableSurface::create(std::move(*loaded), planes, 2);
  if (!surface) return surface.error();
  auto owned = std::make_unique<mesh::DeformableSurface>(std::move(*surface));
  auto scene = rayMarchSceneFor(*owned, stem, aspect, closeUp);
  if (!scene) return scene.error();
  scene->owned = std::move(owned);
  return scene;
}

Result<RayMarchScene> rayMarchSceneFor(const mesh::DeformableSurface& s, const std::string& stem,
                                       float aspect, bool closeUp) {
  RayMarchScene scene;
  // The build-time 1024 map when there is one, else the committed 128 one.
  auto material = rayMarchMaterialFor(s, stem);
  if (!material) return material.error();
  scene.material = std::move(*material);
  scene.surface = &s;
  scene.pokeSite = studies::topVertex(s.geometricRestPositions());
  // Camera: the whole organ, or a close-up of the poke site seen from above and in front.
  const Bounds3 box = boundsOf(s.geometricRestPositions());
  Float3 lo = box.lo, hi = box.hi;
  const Float3 site = s.geometricRestPositions()[scene.pokeSite];
  if (closeUp) {
    lo = {site.x - 20.0f, site.y - 20.0f, site.z - 8.0f};
    hi = {site.x + 20.0f, site.y + 20.0f, site.z + 2.0f};
  }
  scene.camera = render::frameBoundingBox(lo, hi, aspect, {-0.25f, 0.45f, -1.0f});
  // Key light above the camera; a back light low behind the organ shows light through thin tissue.
  const Float3 c{(lo.x + hi.x) / 2, (lo.y + hi.y) / 2, (lo.z + hi.z) / 2};
  const float r = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  scene.lights = {{{c.x + 0.8f * r, c.y - 1.2f * r, c.z + 2.0f * r}, {2.2f, 2.1f, 2.0f}},
                  {{c.x - 1.5f * r, c.y + 1.5f * r, c.z + 0.3f * r}, {1.2f, 1.1f, 1.0f}}};
  return scene;
}

void pokeScene(RayMarchScene& scene, double fraction, float depthMm) {
  const auto rest = scene.surface->geometricRestPositions();
  std::vector<Float3> normals(rest.size()), positions(rest.begin(), rest.end());
  mesh::computeVertexNormals(rest, scene.surface->geometricTriangles(), normals);
  studies::applyPoke(rest, normals, scene.pokeSite, fraction, depthMm, positions);
  scene.owned->update(positions);
}

std::vector<render::Light> pipelineLights(const RayMarchScene& scene) {
  std::vector<render::Light> out;
  for (const auto& l : scene.lights) {
    render::Light light;
    light.type = render::LightType::Point;
    light.positionMm = l.positionMm;
    light.color = l.radiance;
    light.intensity = 1.0f;
    out.push_back(light);
  }
  return out;
}

render::RayMarchSettings withMaterial(render::RayMarchSettings march, const RayMarchScene& scene,
                                      render::TextureHandle map) {
  return materials::withRayMarchMaterial(std::move(march), scene.material, map);
}

void RayMarchRender::setMarch(const render::RayMarchSettings& march) {
  const render::RayMarchSettings material = settings();
  settings() = march;
  settings().layers = material.layers;
  settings().subsurfaceMaps = material.subsurfaceMaps;
  settings().depthScaleMm = material.depthScaleMm;
  settings().uvPerMm = material.uvPerMm;
}

Result<void> RayMarchRender::upload(const mesh::DeformableSurface& s) {
  return renderer.updateMesh(mesh, {0, s.positions(), s.normals(), s.tangents(), s.planes()});
}

Result<Image8> RayMarchRender::render(int width, int height, double* passMs) {
  auto image = renderer.renderImage(scene, width, height);
  if (image && passMs) {
    const render::PassTiming* pass = renderer.lastTimings().find("ray-march");
    *passMs = pass ? pass->cpuMs : -1.0;
  }
  return image;
}

Result<RayMarchRender> makeRayMarchRender(const RayMarchScene& scene,
                                          const gl::GetProcAddressFn& getProcAddress,
                                          const render::RendererSettings& settings) {
  auto renderer = render::Renderer::create(getProcAddress, settings);
  if (!renderer) return renderer.error();
  const auto& s = *scene.surface;
  auto mesh =
      renderer->createMesh({s.positions(), s.normals(), s.tangents(), s.uvs(), s.triangles(), s.planes()});
  if (!mesh) return mesh.error();
  auto map = renderer->createTexture(scene.material.subsurfaceMap, render::TextureEncoding::LinearData);
  if (!map) return map.error();
  RayMarchRender out{std::move(*renderer), *mesh, *map, {}};
  out.scene.camera = scene.camera;
  out.scene.lights = pipelineLights(scene);
  out.scene.background = kRayMarchBackground;
  out.scene.exposure = 1.0f;
  render::SceneObject organ;
  organ.mesh = *mesh;
  render::RayMarchSettings march;
  march.radianceScale = kRayMarchRadianceScale;
  organ.method = withMaterial(march, scene, *map);
  out.scene.objects.push_back(organ);
  return out;
}

subsurface::MeshView meshView(const RayMarchScene& scene) {
  const auto& s = *scene.surface;
  return {s.positions(), s.normals(),   s.tangents(),          s.planes(),
          s.uvs(),       s.triangles(), scene.material.uvPerMm};
}

subsurface::PinholeCamera pinholeOf(const render::Camera& camera) {
  return {camera.eye, camera.target, camera.up, camera.verticalFovDeg};
}

Result<nlohmann::json> renderRayMarchPng(const RayMarchScene& scene, const render::RayMarchSettings& march,
                                         int width, int height, const std::filesystem::path& png) {
  context::ContextRequest request;
  request.width = request.height = 16;  // the renderer draws into its own framebuffer
  auto context = createAppContext(request);
  if (!context) return context.error();
  render::RendererSettings settings;
  settings.shaders = shaderSettingsFromEnvironment();
  settings.finishPasses = true;  // the ray-march pass is timed to completion
  auto gpu = makeRayMarchRender(scene, (*context)->procAddressFunction(), settings);
  if (!gpu) return gpu.error();
  gpu->setMarch(march);
  double passMs = 0.0;
  auto image = gpu->render(width, height, &passMs);
  if (!image) return image.error();
  if (auto w = writePng(png, *image); !w) return w.error();
  nlohmann::json out;
  out["out"] = png.string();
  out["pass_ms"] = passMs;
  out["gl_renderer"] = (*context)->info().renderer;
  out["adaptive"] = march.adaptive;
  if (march.adaptive)
    out["max_samples"] = march.maxSamples;
  else
    out["samples"] = march.samples;
  return out;
}

int runRayMarchRender(const std::string& meshFile, const std::string& png, int width, int height, int samples,
                      bool adaptive, const GlobalOptions& global) {
  auto scene = loadRayMarchScene(meshFile, float(width) / float(height), false);
  if (!scene) return fail("render", scene.error().message);
  render::RayMarchSettings settings;
  settings.samples = std::clamp(samples, 1, 256);
  settings.adaptive = adaptive;
  settings.radianceScale = kRayMarchRadianceScale;
  auto done = renderRayMarchPng(*scene, settings, width, height, png);
  if (!done) return fail("render", done.error().message);
  (*done)["method"] = "raymarch";
  printResult(global, *done);
  return 0;
}

nlohmann::json renderPokedOrganRayMarch(const mesh::DeformableSurface& surface, const std::string& stem,
                                        const std::filesystem::path& outDir, int width, int height) {
  nlohmann::json report = nlohmann::json::array();
  for (bool closeUp : {false, true}) {
    auto scene = rayMarchSceneFor(surface, stem, float(width) / float(height), closeUp);
    if (!scene) return {{"skipped", scene.error().message}};
    // Adaptive quality: a quarter of the 100-sample cost (docs/RESULTS.md), so the main job stays quick.
    render::RayMarchSettings settings;
    settings.adaptive = true;
    settings.radianceScale = kRayMarchRadianceScale;
    const std::string name = std::string("frame_poked_raymarch") + (closeUp ? "_closeup" : "") + ".png";
    auto done = renderRayMarchPng(*scene, settings, width, height, outDir / name);
    if (!done) return {{"skipped", done.error().message}};
    report.push_back(*done);
  }
  return report;
}

}  // namespace tissue::sim_app
