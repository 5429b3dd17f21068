// An organ ready for texture-space diffusion, the skin Gaussians, their CPU reference table
// (texture_space_organ.h).
#include "tissue/studies/texture_space_organ.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include "tissue/core/vec_math.h"
#include "tissue/mesh/deformable_surface.h"
#include "tissue/mesh/load_mesh.h"
#include "tissue/mesh/tangent_frames.h"
#include "tissue/mesh/vertex_normals.h"
#include "tissue/optics/kernel_gaussians.h"
#include "tissue/scene/organ_assets.h"

namespace tissue::studies {
namespace {

Result<TsdOrgan> loadOrgan(const std::filesystem::path& path, float scale, bool allowAtlas) {
  if (allowAtlas) {
    // The scene module's organ loading: the file's UVs when usable, else the automatic atlas,
    // computed once on the rest shape (no material file: these commands bring their own profile).
    scene::OrganSource source;
    source.mesh = path;
    source.meshScaleToMm = scale;
    auto assets = scene::loadOrganAssets(source);
    if (!assets) return assets.error();
    TsdOrgan organ = tsdOrganOf(std::move(assets->mesh));
    organ.atlas = assets->atlas;
    organ.charts = assets->atlasCharts;
    return organ;
  }
  auto loaded = mesh::loadMesh(path, {.requireUvs = false, .scaleToMm = scale});
  if (!loaded) return loaded.error();
  return tsdOrganOf(std::move(*loaded));
}

}  // namespace

TsdOrgan tsdOrganOf(SurfaceMesh mesh) {
  TsdOrgan organ;
  organ.mesh = std::move(mesh);
  SurfaceMesh& m = organ.mesh;
  // Normals per geometric vertex (smooth across seams), tangent frames from the UVs.
  const std::vector<Float3> geo = mesh::geometricPositionsOf(m);
  std::vector<Float3> geoNormals(m.geometricVertexCount);
  mesh::computeVertexNormals(geo, mesh::geometricTrianglesOf(m), geoNormals);
  gatherToRenderVertices(m, geoNormals, organ.normals);
  organ.tangents.resize(m.positions.size());
  if (m.hasUvs()) {
    mesh::computeTangentFrames(m.positions, m.uvs, m.triangles, organ.normals, organ.tangents,
                               m.geometricIndex);
    organ.uvDensity = render::uvDensity(m.positions, m.uvs, m.triangles);
  }
  const Bounds3 box = boundsOf(m.positions);
  organ.lo = box.lo, organ.hi = box.hi;
  return organ;
}

Result<TsdOrgan> loadTsdOrgan(const std::filesystem::path& path, float scale) {
  return loadOrgan(path, scale, true);
}

Result<TsdOrgan> loadRenderMesh(const std::filesystem::path& path, float scale) {
  return loadOrgan(path, scale, false);
}

Result<std::vector<render::ProfileGaussian>> skinGaussians(const std::filesystem::path& path, int count) {
  if (count != 2 && count != 4 && count != 6)
    return Error{"the skin profile has 2, 4 or 6 Gaussians, not " + std::to_string(count)};
  // Step 1: the six terms from the reference table.
  std::ifstream in(path);
  if (!in) return Error{"cannot read " + path.string()};
  std::vector<render::ProfileGaussian> six;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.starts_with("variance")) continue;
    std::istringstream row(line);
    render::ProfileGaussian g;
    if (!(row >> g.varianceMm2 >> g.weight.x >> g.weight.y >> g.weight.z))
      return Error{path.string() + ": a row is not 'variance w_R w_G w_B': " + line};
    six.push_back(g);
  }
  if (six.size() != 6) return Error{path.string() + ": expected 6 Gaussians"};
  if (count == 6) return six;
  // Step 2: fewer terms fitted to the six-term profile by optics::fitGaussians (branch
  // kernels: Nelder-Mead over the shared variances, non-negative weights per channel).
  optics::RadialProfileRgb profile;
  profile.name = "d'Eon skin";
  for (int i = 0; i <= 4000; ++i) {
    const double r = 0.005 * i;
    const Float3 v = render::evaluateGaussianSum(six, float(r));
    profile.radiusMm.push_back(r);
    profile.value[0].push_back(double(v.x)), profile.value[1].push_back(double(v.y));
    profile.value[2].push_back(double(v.z));
  }
  auto sum = optics::fitGaussians(profile, count);
  if (!sum) return sum.error();
  std::vector<render::ProfileGaussian> fit;
  for (std::size_t i = 0; i < sum->varianceMm2.size(); ++i)
    fit.push_back({float(sum->varianceMm2[i]),
                   {float(sum->weights[0][i]), float(sum->weights[1][i]), float(sum->weights[2][i])}});
  return fit;
}

render::RadialProfileTable skinProfileTable(const std::vector<render::ProfileGaussian>& six,
                                            float& cutoffMm) {
  float widest = 0.0f;
  for (const auto& g : six)
    widest = std::max(widest, g.varianceMm2);
  cutoffMm = 3.5f * std::sqrt(widest);  // R at 3.5 sigma of the widest term: < 0.3% of its peak
  render::RadialProfileTable table;
  for (int i = 0; i <= 4000; ++i) {
    table.radiusMm.push_back(cutoffMm * float(i) / 4000.0f);
    table.value.push_back(render::evaluateGaussianSum(six, table.radiusMm.back()));
  }
  return table;
}

}  // namespace tissue::studies
