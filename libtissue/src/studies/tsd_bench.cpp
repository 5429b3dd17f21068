// The scenes of the texture-space speed-up table (tsd_bench.h).
#include "tissue/studies/tsd_bench.h"

#include <algorithm>
#include <cmath>

namespace tissue::studies {

render::Scene tsdBenchScene(Float3 target, float distance, float organSize, float rowLength) {
  render::Scene scene;
  const float dy = -0.35f, dz = -1.0f, n = std::hypot(dy, dz);
  scene.camera.target = target;
  scene.camera.eye = {target.x, target.y - dy / n * distance, target.z - dz / n * distance};
  scene.camera.nearMm = std::max(distance - organSize, distance * 0.05f);
  scene.camera.farMm = std::hypot(distance + organSize, rowLength);
  scene.lights[0].positionMm = {target.x + 0.6f * distance, target.y + 0.9f * distance, target.z + distance};
  return scene;
}

float TsdOrganRow::rowX(int i) const {
  return (float(i) - 0.5f * float(kMaxObjects - 1)) * 1.1f * widthMm;
}

render::Scene TsdOrganRow::sceneOf(int n, float distance, const render::TextureSpaceSettings& method) const {
  const int first = kMaxObjects / 2 - (n + 1) / 2;
  const float middle = 0.5f * (rowX(first) + rowX(first + n - 1));
  render::Scene scene = tsdBenchScene({middle, 0, 0}, distance, sizeMm, float(n) * 1.1f * widthMm);
  for (int i = first; i < first + n; ++i) {
    render::SceneObject object;
    object.mesh = meshes[std::size_t(i)];
    object.method = method;
    scene.objects.push_back(object);
  }
  return scene;
}

Result<TsdOrganRow> uploadOrganRow(render::Renderer& renderer, const TsdOrgan& organ) {
  TsdOrganRow row;
  const Float3 centre{0.5f * (organ.lo.x + organ.hi.x), 0.5f * (organ.lo.y + organ.hi.y),
                      0.5f * (organ.lo.z + organ.hi.z)};
  row.widthMm = organ.hi.x - organ.lo.x;
  row.sizeMm = std::hypot(row.widthMm, organ.hi.y - organ.lo.y, organ.hi.z - organ.lo.z);
  std::vector<Float3> positions(organ.mesh.positions.size());
  for (int i = 0; i < TsdOrganRow::kMaxObjects; ++i) {
    for (std::size_t v = 0; v < positions.size(); ++v) {
      const Float3 p = organ.mesh.positions[v];
      positions[v] = {p.x - centre.x + row.rowX(i), p.y - centre.y, p.z - centre.z};
    }
    render::MeshArrays arrays = organ.arrays();
    arrays.positions = positions;
    auto handle = renderer.createMesh(arrays);
    if (!handle) return handle.error();
    row.meshes.push_back(*handle);
  }
  return row;
}

}  // namespace tissue::studies
