#include "raymarch_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "deformations.h"
#include "output.h"
#include "tissue/mesh/load_mesh.h"
#include "tissue/mesh/vertex_normals.h"
#include "tissue/optics/schlick_phase.h"

namespace tissue::sim_app {
namespace {

float minSigmaT(const subsurface::LayerCoefficients& l) {
  return std::min({l.sigma_t.x, l.sigma_t.y, l.sigma_t.z});
}

}  // namespace

Result<RayMarchScene> loadRayMarchScene(const std::filesystem::path& meshFile, float aspect, bool closeUp) {
  RayMarchScene scene;
  const std::string stem = meshFile.stem().string();
  const auto materialFile = dataDir() / "materials" / (stem + ".json");
  auto stack = subsurface::loadLayerStack(materialFile, dataDir());
  if (!stack) return Error{stack.error().message + " (ray marching needs a data/ mesh with a material file)"};
  scene.stack = std::move(*stack);
  // The build-time 1024 map when there is one, else the committed 128 one.
  auto map = readImage(findDataTexture(stem, "subsurface"), 4);
  if (!map) return Error{"subsurface map of " + stem + ": " + map.error().message};
  scene.subsurfaceMap = std::move(*map);
  auto maps = subsurface::subsurfaceMapsFromImages(std::span<const Image8>(&scene.subsurfaceMap, 1));
  if (!maps) return maps.error();
  scene.stack.maps = std::move(*maps);
  auto loaded = mesh::loadMesh(meshFile, {.requireUvs = true});
  if (!loaded) return loaded.error();
  // Plane neighbourhoods from the first layer's extinction (François eq. 8).
  mesh::PlaneFitSettings planes;
  planes.sigma_t = minSigmaT(scene.stack.layers[0]);
  auto surface = mesh::DeformableSurface::create(std::move(*loaded), planes, 2);
  if (!surface) return surface.error();
  scene.surface = std::make_unique<mesh::DeformableSurface>(std::move(*surface));
  const auto& s = *scene.surface;
  scene.uvPerMm = subsurface::uvPerMmOf(s.positions(), s.uvs(), s.triangles());
  scene.pokeSite = topVertex(s.geometricRestPositions());
  // Camera: the whole organ, or a close-up of the poke site seen from above and in front.
  Float3 lo{std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
            std::numeric_limits<float>::max()};
  Float3 hi{-lo.x, -lo.y, -lo.z};
  for (const Float3& p : s.geometricRestPositions()) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
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
  applyPoke(rest, normals, scene.pokeSite, fraction, depthMm, positions);
  scene.surface->update(positions);
}

render::RayMarchMaterial gpuMaterial(const RayMarchScene& scene) {
  render::RayMarchMaterial m;
  for (const auto& l : scene.stack.layers)
    m.layers.push_back({l.sigma_s, l.sigma_t, float(optics::schlickKFromG(l.g))});
  m.subsurfaceMaps = {scene.subsurfaceMap};
  m.depthScaleMm = scene.stack.depthScaleMm;
  m.uvPerMm = scene.uvPerMm;
  return m;
}

std::vector<render::RayMarchLight> gpuLights(const RayMarchScene& scene) {
  std::vector<render::RayMarchLight> out;
  for (const auto& l : scene.lights)
    out.push_back({l.positionMm, l.radiance});
  return out;
}

subsurface::MeshView meshView(const RayMarchScene& scene) {
  const auto& s = *scene.surface;
  return {s.positions(), s.normals(), s.tangents(), s.planes(), s.uvs(), s.triangles(), scene.uvPerMm};
}

subsurface::PinholeCamera pinholeOf(const render::Camera& camera) {
  return {camera.eye, camera.target, camera.up, camera.verticalFovDeg};
}

Result<render::RayMarchRenderer> makeRayMarchRenderer(const RayMarchScene& scene,
                                                      const gl::GetProcAddressFn& getProcAddress) {
  auto renderer = render::RayMarchRenderer::create(getProcAddress);
  if (!renderer) return renderer.error();
  const auto& s = *scene.surface;
  if (auto r =
          renderer->setMesh({s.positions(), s.normals(), s.tangents(), s.uvs(), s.triangles()}, s.planes());
      !r)
    return r.error();
  if (auto r = renderer->setMaterial(gpuMaterial(scene)); !r) return r.error();
  return renderer;
}

}  // namespace tissue::sim_app
