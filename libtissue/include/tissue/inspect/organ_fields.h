#pragma once
/// \file
/// The fields the inspection views and the ParaView series show, computed from plain arrays
/// (no VTK, no simulator types): spring strain and vertex stretch, the local-plane residual,
/// handedness flips at UV seams and the texture-space stretch. What the mesh module already
/// computes (planes, normals, tangents, neighbourhoods) comes in as input, never recomputed.
/// Built the same with and without VTK.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "tissue/core/types.h"

namespace tissue::inspect {

/// A spring (or an edge) between two vertices.
using Edge = std::array<std::uint32_t, 2>;

/// Engineering strain of each spring, L / L0 - 1 (unitless; 0 at rest, > 0 stretched).
/// \param positions   #N node positions, mm
/// \param edges       #S springs over the nodes
/// \param restLengths #S rest lengths L0, mm (> 0)
std::vector<float> springStrain(std::span<const Float3> positions, std::span<const Edge> edges,
                                std::span<const double> restLengths);

/// Stretch of each vertex: the mean L / L0 of its springs (unitless; 1 at rest, and 1 for a
/// vertex without springs).
/// \param vertexCount #N
/// \param edges       #S springs over the nodes
/// \param strain      #S from springStrain
std::vector<float> vertexStretch(std::size_t vertexCount, std::span<const Edge> edges,
                                 std::span<const float> strain);

/// The residual of each local plane (François et al. 2006 §2.2, eq. 7-8 and 14): the RMS
/// distance (mm) of the vertex's neighbours from its plane N_S . (p - P_V) = 0, with
/// P_V = V + d N_V. Zero for a flat neighbourhood; it grows with the curvature inside the
/// sphere of radius -log(eps) / sigma_t.
/// \param positions  #V positions, mm
/// \param normals    #V unit vertex normals N_V
/// \param planes     #V planes (N_S, d mm), as mesh::IncrementalPlaneFitter gives them
/// \param offsets    #V + 1 offsets of the neighbourhoods (mesh::Neighbourhoods)
/// \param neighbours neighbour indices (mesh::Neighbourhoods)
std::vector<float> planeResidualMm(std::span<const Float3> positions, std::span<const Float3> normals,
                                   std::span<const Float4> planes, std::span<const std::uint32_t> offsets,
                                   std::span<const std::uint32_t> neighbours);

/// 1 for each render vertex whose geometric vertex has a copy (across a UV seam) of the other
/// handedness w, else 0: where normal mapping mirrors (tangent_frames.h keeps such copies apart).
/// \param tangents       #R (T, w), w = +1 or -1
/// \param geometricIndex #R geometric vertex of each render vertex
std::vector<float> handednessFlips(std::span<const Float4> tangents,
                                   std::span<const std::uint32_t> geometricIndex);

/// Texture-space stretch of each triangle: sqrt(|dP/du| |dP/dv|) (mm per UV unit, d'Eon et al.
/// 2007 §3.2's stretch map, as render::uvStretch computes it) times the map's mean density
/// sqrt(UV area / surface area): unitless, 1 where the triangle has the atlas's mean density,
/// 2 where a texel covers twice the length. Both factors are given by the caller.
/// \param stretchMmPerUv #F (|dP/du|, |dP/dv|), mm per UV unit
/// \param uvPerMm        the density, UV units per mm (render::uvDensity)
std::vector<float> relativeTextureStretch(std::span<const Float2> stretchMmPerUv, float uvPerMm);

/// Per-vertex arrays averaged onto triangles (cell data): the mean of the three corners.
std::vector<float> triangleMeans(std::span<const float> perVertex, std::span<const Triangle> triangles);

}  // namespace tissue::inspect
