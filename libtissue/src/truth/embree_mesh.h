#pragma once
// Private: the Embree back end of RayMesh (embree_mesh.cpp with Embree, embree_missing.cpp without).

#include <memory>
#include <span>

#include "tissue/truth/ray_mesh.h"

namespace tissue::truth::detail {

/// Whether embree_mesh.cpp is built in.
bool embreeBuiltIn();

/// An Embree scene over the (validated) mesh, or the reason it could not be built.
Result<std::unique_ptr<RayMesh>> makeEmbreeMesh(std::span<const Float3> positions,
                                                std::span<const Triangle> triangles);

}  // namespace tissue::truth::detail
