#pragma once
/// \file
/// Spring networks: the springs' indices and rest state, struct-of-arrays, built from a surface
/// mesh (edge springs plus bending springs across shared edges). Stiffness and damping are stored
/// in internal units (g/s^2 and g/s, see units.h); the config takes N/mm and N*s/mm.

#include <cstdint>
#include <span>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/types.h"

namespace tissue::sim {

/// How the stiffness of each spring follows from SpringConfig::stiffness.
enum class StiffnessLaw {
  Constant,       ///< k_i = k: `stiffness` is in N/mm
  PerRestLength,  ///< k_i = k / L0_i (SOFA's MeshSpringForceField): `stiffness` is in N (N/mm per mm)
};

/// How to build springs from a surface mesh.
struct SpringConfig {
  double stiffness = 0.1;         ///< N/mm (Constant) or N (PerRestLength), edge springs
  double bendingStiffness = 0.0;  ///< same unit as `stiffness`; 0 builds no bending springs
  StiffnessLaw law = StiffnessLaw::Constant;
  double damping = 0.0;  ///< N*s/mm, along each spring on the relative velocity
};

/// What a surface build found (for reports).
struct SpringBuildReport {
  std::size_t edgeSprings = 0;       ///< one per unique mesh edge
  std::size_t bendingSprings = 0;    ///< one per edge shared by exactly two triangles
  std::size_t nonManifoldEdges = 0;  ///< edges with more than two triangles (no bending spring)
  std::size_t boundaryEdges = 0;     ///< edges with one triangle (no bending spring)
};

/// Springs as struct-of-arrays, plus each vertex's incident springs (CSR) so that the force
/// pass can gather per vertex in a fixed order (deterministic with any number of threads).
struct SpringNetwork {
  std::vector<std::uint32_t> i;                    ///< first end point, #springs
  std::vector<std::uint32_t> j;                    ///< second end point, #springs
  std::vector<double> restLength;                  ///< L0 in mm, #springs, > 0
  std::vector<double> stiffness;                   ///< k in g/s^2 (1e-6 N/mm), #springs
  std::vector<double> damping;                     ///< c in g/s (1e-6 N*s/mm), #springs
  std::vector<std::uint32_t> vertexSpringOffsets;  ///< #vertices + 1 offsets into vertexSprings
  std::vector<std::uint32_t> vertexSprings;        ///< incident spring indices, ascending per vertex

  std::size_t size() const { return i.size(); }
  std::size_t vertexCount() const { return vertexSpringOffsets.empty() ? 0 : vertexSpringOffsets.size() - 1; }
};

/// Adds one spring with rest length from `restLengthMm` (mm), stiffness `stiffnessNPerMm`
/// (N/mm, converted) and damping `dampingNsPerMm` (N*s/mm). Call finalizeSpringNetwork after.
void addSpring(SpringNetwork& network, std::uint32_t i, std::uint32_t j, double restLengthMm,
               double stiffnessNPerMm, double dampingNsPerMm);

/// Builds the per-vertex incidence lists for `vertexCount` vertices. Fails on an index out of
/// range, a spring from a vertex to itself or a rest length that is not positive and finite.
Result<void> finalizeSpringNetwork(SpringNetwork& network, std::size_t vertexCount);

/// Edge springs for every unique edge of `triangles` and, when config.bendingStiffness > 0, a
/// bending spring between the two opposite vertices of every edge shared by two triangles.
/// Rest lengths come from `positions` (mm). Fails on bad indices or coincident vertices.
Result<SpringNetwork> buildSurfaceSprings(std::span<const Float3> positions,
                                          std::span<const Triangle> triangles, const SpringConfig& config,
                                          SpringBuildReport* report = nullptr);

}  // namespace tissue::sim
