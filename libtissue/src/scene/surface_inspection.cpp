// The surface's shading fields for ParaView (surface_inspection.h).
#include "tissue/scene/surface_inspection.h"

#include <vector>

#include "tissue/core/vec_math.h"
#include "tissue/inspect/vtk_export.h"

namespace tissue::scene {

Result<void> writeSurfaceVtp(const mesh::DeformableSurface& surface, const std::filesystem::path& vtp) {
  const auto& m = surface.mesh();
  const auto rest = surface.geometricRestPositions();
  std::vector<Float3> planeNormal(m.positions.size());
  std::vector<float> planeOffset(m.positions.size()), displacement(m.positions.size());
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const auto& p = surface.planes()[i];
    planeNormal[i] = {p.x, p.y, p.z};
    planeOffset[i] = p.w;
    displacement[i] = length(m.positions[i] - rest[m.geometricIndex[i]]);
  }
  return inspect::writeVtp(vtp, m.positions, m.triangles,
                           {inspect::fieldOf<Float3>("normal", surface.normals()),
                            inspect::fieldOf<Float4>("tangent_handedness", surface.tangents()),
                            inspect::fieldOf<Float3>("plane_normal", std::span<const Float3>(planeNormal)),
                            {"plane_offset_mm", 1, planeOffset},
                            {"displacement_mm", 1, displacement}});
}

}  // namespace tissue::scene
