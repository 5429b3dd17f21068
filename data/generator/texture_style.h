#pragma once
/// \file
/// The look of each mesh's layer textures: palette, seeds and feature sizes.

#include <cstdint>

#include <Eigen/Core>

#include "uv_layout.h"
#include "vessels.h"

namespace tissue::datagen {

/// Palette (sRGB in [0, 1]) and procedural parameters of one mesh's textures.
struct TextureStyle {
  std::uint64_t seed = 1;
  Eigen::Vector3d outerColor;        ///< outer layer diffuse colour
  Eigen::Vector3d fatColor;          ///< fat lobules seen through the outer layer
  Eigen::Vector3d vesselColor;       ///< vessels seen through the outer layer
  Eigen::Vector3d innerColor;        ///< inner layer base colour
  Eigen::Vector3d innerVesselColor;  ///< vessels in the inner layer
  double lobuleCellMm = 3.0;         ///< fat lobule (Worley cell) size, mm
  double fatCoverage = 0.5;          ///< fraction of the surface with fat lobules, 0..1
  double fineScaleMm = 1.2;          ///< size of the fine surface relief, mm
  PatternSurface surface;            ///< where the vessels grow
  VesselGrowth thickVessels;
  VesselGrowth thinVessels;
};

/// The style of `kind`: patch = peritoneum pink with yellowish fat; liver = reddish brown with
/// few lobules; tube = bowel pink with mesenteric vessels.
TextureStyle textureStyle(MeshKind kind);

}  // namespace tissue::datagen
