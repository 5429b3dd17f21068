#pragma once
/// \file
/// The three organ-like meshes, in mm, built deterministically (fixed seeds).

#include "uv_mesh.h"

namespace tissue::datagen {

/// Abdominal-wall-like patch, 80 x 60 mm, 115 x 87 vertices: a gently domed height field with
/// soft bumps, outside = +z, planar UVs (one chart). Its open border is the pinnable region.
UvMesh makePatch();

/// Closed liver-like organ, about 180 x 120 x 80 mm, genus 0: a cube-sphere (6 faces of 48 x 48
/// quads) displaced into a flattened shape with a large right lobe (+x), a thin left lobe (-x) and
/// an anterior notch. UV atlas: one square chart per cube face in a 3 x 2 layout.
UvMesh makeLiver();

/// Bowel/vessel segment: a tube of radius 8-12 mm around a gently curved centreline about
/// 150 mm long, 64 vertices around x 150 rings; u around (seam with duplicated `vt`), v along.
/// Both ends are open.
UvMesh makeTube();

}  // namespace tissue::datagen
