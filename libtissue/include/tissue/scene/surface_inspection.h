#pragma once
/// \file
/// A deforming surface with the fields its shading depends on, written for ParaView: the shading
/// normals, the tangent frames (xyz and handedness w), the local planes of subsurface texture
/// mapping (François et al. 2006 eq. 14: normal and offset) and each vertex's displacement from
/// rest (mm). The demo writes one for the poked organ; inspection views build on it.

#include <filesystem>

#include "tissue/core/result.h"
#include "tissue/mesh/deformable_surface.h"

namespace tissue::scene {

/// Writes `surface` as a .vtp file (atomically) with the arrays normal, tangent_handedness,
/// plane_normal, plane_offset_mm and displacement_mm. Errors when VTK is not built in
/// (inspect::builtWithVtk()) or the file cannot be written.
Result<void> writeSurfaceVtp(const mesh::DeformableSurface& surface, const std::filesystem::path& vtp);

}  // namespace tissue::scene
