// The demo's texture-space diffusion frame of the poked organ.
#include "demo_texture_space.h"

#include <algorithm>
#include <cmath>

#include "output.h"
#include "texture_space_setup.h"
#include "tissue/context/headless_context.h"
#include "tissue/core/stopwatch.h"
#include "tissue/mesh/tangent_frames.h"
#include "tissue/mesh/uv_atlas.h"
#include "tissue/mesh/vertex_normals.h"
#include "tissue/render/texture_space.h"

namespace tissue::sim_app {
namespace {

/// Render arrays with usable UVs: the surface's own, or the atlas of its rest shape with the
/// current positions gathered through the atlas's vertex map.
struct Arrays {
  std::vector<Float3> positions, normals;
  std::vector<Float4> tangents;
  std::vector<Float2> uvs;
  std::vector<Triangle> triangles;
  bool atlas = false;
};

Result<Arrays> usableArrays(const mesh::DeformableSurface& s) {
  Arrays a;
  if (mesh::hasUsableUvs(s.uvs(), s.triangles(), s.positions().size())) {
    a.positions.assign(s.positions().begin(), s.positions().end());
    a.normals.assign(s.normals().begin(), s.normals().end());
    a.tangents.assign(s.tangents().begin(), s.tangents().end());
    a.uvs.assign(s.uvs().begin(), s.uvs().end());
    a.triangles.assign(s.triangles().begin(), s.triangles().end());
    return a;
  }
  auto atlas = mesh::computeUvAtlas(s.geometricRestPositions(), s.geometricTriangles());
  if (!atlas) return atlas.error();
  std::vector<Float3> geoNormals(s.geometricPositions().size());
  mesh::computeVertexNormals(s.geometricPositions(), s.geometricTriangles(), geoNormals);
  for (std::uint32_t v : atlas->originalVertex) {
    a.positions.push_back(s.geometricPositions()[v]);
    a.normals.push_back(geoNormals[v]);
  }
  a.uvs = atlas->uvs;
  a.triangles = atlas->triangles;
  a.tangents.resize(a.positions.size());
  mesh::computeTangentFrames(a.positions, a.uvs, a.triangles, a.normals, a.tangents, atlas->originalVertex);
  a.atlas = true;
  return a;
}

}  // namespace

nlohmann::json renderTextureSpaceDemo(const mesh::DeformableSurface& surface,
                                      const std::filesystem::path& png, int width, int height) {
  constexpr int kMapSize = 1024;
  auto arrays = usableArrays(surface);
  if (!arrays) return {{"skipped", arrays.error().message}};
  auto gaussians = skinGaussians(6);
  if (!gaussians) return {{"skipped", gaussians.error().message}};
  auto context = context::createHeadlessContext({}, {.backend = "", .log = false});
  if (!context) return {{"skipped", context.error().message}};
  auto renderer = render::TextureSpaceRenderer::create((*context)->procAddressFunction(),
                                                       {.shaders = {}, .maxMapSize = kMapSize});
  if (!renderer) return {{"skipped", renderer.error().message}};
  // UV density for d_ref (eq. 3): sqrt(UV area / surface area).
  double uv = 0.0, area = 0.0;
  Float3 lo = arrays->positions.front(), hi = lo;
  for (const Triangle& t : arrays->triangles) {
    const Float2 a = arrays->uvs[t[0]], b = arrays->uvs[t[1]], c = arrays->uvs[t[2]];
    uv += 0.5 * std::abs(double(b.x - a.x) * double(c.y - a.y) - double(b.y - a.y) * double(c.x - a.x));
    const Float3 p = arrays->positions[t[0]], q = arrays->positions[t[1]], r = arrays->positions[t[2]];
    const double ex = double(q.x - p.x), ey = double(q.y - p.y), ez = double(q.z - p.z);
    const double fx = double(r.x - p.x), fy = double(r.y - p.y), fz = double(r.z - p.z);
    area += 0.5 * std::hypot(ey * fz - ez * fy, ez * fx - ex * fz, ex * fy - ey * fx);
  }
  for (const Float3& p : arrays->positions)
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)},
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  const render::MeshArrays mesh{arrays->positions, arrays->normals,   arrays->tangents,
                                arrays->uvs,       arrays->triangles, {}};
  if (auto r = renderer->setMesh(mesh, float(std::sqrt(uv / area)) * kMapSize); !r)
    return {{"skipped", r.error().message}};
  if (const auto base = findDataTexture("liver", "base_color"); !arrays->atlas && !base.empty())
    if (auto image = readImage(base, 4); image) (void)renderer->setBaseColor(*image);
  // The demo's view: frame the organ; light above right of the camera.
  render::Scene scene;
  scene.camera = render::frameBoundingBox(lo, hi, float(width) / float(height));
  const Float3 e = scene.camera.eye;
  scene.lights[0].positionMm = {e.x + 0.5f * (hi.x - lo.x), e.y + (hi.y - lo.y), e.z};
  render::TsdSettings settings;
  settings.gaussians = *gaussians;
  Stopwatch watch;
  auto image = renderer->renderImage(scene, width, height, settings);
  if (!image) return {{"skipped", image.error().message}};
  const double ms = watch.elapsedMs();
  if (auto w = writePng(png, *image); !w) return {{"skipped", w.error().message}};
  return {{"image", png.filename().string()},
          {"ms", ms},
          {"map_size", kMapSize},
          {"uvs", arrays->atlas ? "automatic atlas" : "the mesh's own"},
          {"gaussians", gaussians->size()}};
}

}  // namespace tissue::sim_app
