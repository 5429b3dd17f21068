#pragma once
/// \file
/// Procedural deformations for the benchmarks (re-fit, ray-march, frame path): a local poke and a
/// smooth global bend, deterministic, so a bench moves the same vertices on every run. GL-free.

#include <cstdint>
#include <span>
#include <vector>

#include "tissue/core/types.h"

namespace tissue::studies {

/// A poke: the `fraction` of vertices nearest to `centerVertex` (Euclidean, rest state) are
/// pushed along -normal by up to `depthMm` with a smooth (cosine) falloff to zero at the edge
/// of the region, so exactly those vertices move.
/// \return the indices of the moved vertices
std::vector<std::uint32_t> applyPoke(std::span<const Float3> rest, std::span<const Float3> normals,
                                     std::uint32_t centerVertex, double fraction, float depthMm,
                                     std::span<Float3> out);

/// A smooth global deformation moving every vertex: a bend about the bounding box's long axis
/// plus a low-frequency ripple of amplitude `amplitudeMm`.
void applyGlobalBend(std::span<const Float3> rest, float amplitudeMm, std::span<Float3> out);

/// The vertex farthest along +z (a deterministic, visible poke site for a camera above).
std::uint32_t topVertex(std::span<const Float3> positions);

}  // namespace tissue::studies
