// An organ ready for ray marching (raymarch_scene.h): the scene module's organ layer for the
// mesh, material and subsurface map; the framing, lights and poke the ray-march commands share.
#include "tissue/studies/raymarch_scene.h"

#include <algorithm>
#include <filesystem>
#include <utility>

#include "tissue/core/vec_math.h"
#include "tissue/mesh/vertex_normals.h"
#include "tissue/scene/material_file.h"
#include "tissue/studies/deformations.h"

namespace tissue::studies {
namespace {

/// The layer stack of `organ`'s material with its subsurface map (scene::layerStack), and the
/// texture units per mm of `s` (measured on its current shape, as the march uses it).
Result<materials::RayMarchMaterial> rayMarchMaterialFor(const mesh::DeformableSurface& s,
                                                        const scene::OrganAssets& organ) {
  if (organ.material.textures.subsurface.empty())
    return Error{organ.material.file.string() + ": ray marching needs textures.subsurface (docs/DATA.md)"};
  if (!organ.subsurfaceMap)
    return Error{organ.material.file.string() +
                 ": its subsurface map belongs to the file's UVs, and this organ has the automatic atlas"};
  materials::RayMarchMaterial m;
  m.subsurfaceMap = *organ.subsurfaceMap;
  auto stack = scene::layerStack(organ.material, m.subsurfaceMap);
  if (!stack) return stack.error();
  m.stack = std::move(*stack);
  m.uvPerMm = subsurface::uvPerMmOf(s.positions(), s.uvs(), s.triangles());
  return m;
}

}  // namespace

Result<RayMarchScene> loadRayMarchScene(scene::OrganSource source, float aspect, bool closeUp) {
  source.uvAtlasFallback = false;  // the subsurface map is painted on the file's UVs
  auto organ = scene::loadOrganAssets(source);
  if (!organ && !std::filesystem::is_regular_file(source.material))
    return Error{organ.error().message + " (ray marching needs a mesh with a material file)"};
  if (!organ) return organ.error();
  // Plane neighbourhoods from the first layer's extinction (François eq. 8).
  auto surface = mesh::DeformableSurface::create(organ->mesh, organ->planes, 2);
  if (!surface) return surface.error();
  auto owned = std::make_unique<mesh::DeformableSurface>(std::move(*surface));
  auto scene = rayMarchSceneFor(*owned, *organ, aspect, closeUp);
  if (!scene) return scene.error();
  scene->owned = std::move(owned);
  return scene;
}

Result<RayMarchScene> rayMarchSceneFor(const mesh::DeformableSurface& s, const scene::OrganAssets& organ,
                                       float aspect, bool closeUp) {
  RayMarchScene scene;
  auto material = rayMarchMaterialFor(s, organ);
  if (!material) return material.error();
  scene.material = std::move(*material);
  scene.surface = &s;
  scene.pokeSite = topVertex(s.geometricRestPositions());
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

Result<void> pokeScene(RayMarchScene& scene, double fraction, float depthMm) {
  if (!scene.owned) return Error{"pokeScene: the scene does not own its surface (loadRayMarchScene)"};
  const auto rest = scene.surface->geometricRestPositions();
  std::vector<Float3> normals(rest.size()), positions(rest.begin(), rest.end());
  mesh::computeVertexNormals(rest, scene.surface->geometricTriangles(), normals);
  applyPoke(rest, normals, scene.pokeSite, fraction, depthMm, positions);
  scene.owned->update(positions);
  return {};
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

}  // namespace tissue::studies
