#include "texture_style.h"

namespace tissue::datagen {
namespace {

VesselGrowth thick(std::uint64_t seed, int roots, double radiusMm) {
  VesselGrowth g;
  g.seed = seed;
  g.roots = roots;
  g.rootRadiusMm = radiusMm;
  g.minRadiusMm = 0.35;
  g.stepMm = 1.0;
  g.taperPerStep = 0.993;
  g.branchProbability = 0.035;
  g.wiggle = 0.05;
  return g;
}

VesselGrowth thin(std::uint64_t seed, int roots, double radiusMm) {
  VesselGrowth g;
  g.seed = seed;
  g.roots = roots;
  g.rootRadiusMm = radiusMm;
  g.minRadiusMm = 0.1;
  g.stepMm = 0.5;
  g.taperPerStep = 0.992;
  g.branchProbability = 0.06;
  g.wiggle = 0.09;
  return g;
}

}  // namespace

TextureStyle textureStyle(MeshKind kind) {
  TextureStyle s;
  switch (kind) {
    case MeshKind::kPatch:
      s.seed = 0x9a7c4u;
      s.outerColor = {0.86, 0.56, 0.55};
      s.fatColor = {0.93, 0.80, 0.50};
      s.vesselColor = {0.62, 0.16, 0.20};
      s.innerColor = {0.62, 0.20, 0.20};
      s.innerVesselColor = {0.30, 0.03, 0.08};
      s.lobuleCellMm = 3.5;
      s.fatCoverage = 0.55;
      s.surface = {PatternShape::kPlane, 0.0, 0.0, {kPatchWidthMm / 2, kPatchHeightMm / 2}};
      s.thickVessels = thick(0x7a7c4101u, 3, 1.3);
      s.thinVessels = thin(0x7a7c4102u, 14, 0.45);
      break;
    case MeshKind::kLiver:
      s.seed = 0x11e5u;
      s.outerColor = {0.52, 0.20, 0.15};
      s.fatColor = {0.66, 0.36, 0.24};
      s.vesselColor = {0.36, 0.08, 0.10};
      s.innerColor = {0.42, 0.10, 0.09};
      s.innerVesselColor = {0.20, 0.02, 0.05};
      s.lobuleCellMm = 1.6;  // hepatic lobules are about 1-2 mm across
      s.fatCoverage = 0.35;
      s.surface = {PatternShape::kSphere, kLiverPatternRadiusMm, 0.0, {0.0, 0.0}};
      s.thickVessels = thick(0x11e5101u, 6, 1.6);
      s.thinVessels = thin(0x11e5102u, 40, 0.5);
      break;
    case MeshKind::kTube:
      s.seed = 0x70be5u;
      s.outerColor = {0.88, 0.62, 0.58};
      s.fatColor = {0.95, 0.84, 0.58};
      s.vesselColor = {0.58, 0.12, 0.18};
      s.innerColor = {0.70, 0.24, 0.24};
      s.innerVesselColor = {0.32, 0.03, 0.09};
      s.lobuleCellMm = 4.0;
      s.fatCoverage = 0.3;
      s.surface = {PatternShape::kCylinder, kTubeMeanRadiusMm, kTubeLengthMm, {0.0, 0.0}};
      s.thickVessels = thick(0x70be5101u, 4, 1.1);  // mesenteric arcades
      s.thinVessels = thin(0x70be5102u, 16, 0.4);   // vasa recta
      break;
  }
  return s;
}

}  // namespace tissue::datagen
