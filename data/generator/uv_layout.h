#pragma once
/// \file
/// The UV layouts of the three generated meshes, shared by the mesh builders (forward: surface
/// parameters to UV) and the texture generator (inverse: texel to a point in pattern space), so
/// the textures live exactly in the meshes' UV space.
///
/// Pattern space is a simple surface in mm on which the procedural patterns are evaluated in 3D,
/// so they are continuous across UV seams: the plane z = 0 (patch), a cylinder of radius
/// kTubeMeanRadiusMm (tube) or a sphere of radius kLiverPatternRadiusMm (liver).

#include <array>

#include <Eigen/Core>

#include "tissue/core/types.h"

namespace tissue::datagen {

/// The three generated meshes (a closed set).
enum class MeshKind { kPatch, kLiver, kTube };

/// All meshes, in output order.
inline constexpr std::array<MeshKind, 3> kAllMeshes = {MeshKind::kPatch, MeshKind::kLiver, MeshKind::kTube};

/// File stem of a mesh ("patch", "liver", "tube").
const char* meshName(MeshKind kind);

/// Empty margin around every chart, in UV units: 8 texels at 1024 x 1024.
inline constexpr double kGutterUv = 8.0 / 1024.0;

inline constexpr double kPatchWidthMm = 80.0;   ///< patch extent along x, mm
inline constexpr double kPatchHeightMm = 60.0;  ///< patch extent along y, mm
inline constexpr int kPatchGridX = 115;         ///< patch vertices along x (about 0.70 mm apart)
inline constexpr int kPatchGridY = 87;          ///< patch vertices along y (about 0.70 mm apart)

inline constexpr int kLiverFaceQuads = 48;             ///< quads per cube-face edge
inline constexpr double kLiverPatternRadiusMm = 60.0;  ///< pattern sphere radius, mm

inline constexpr int kTubeAround = 64;             ///< vertices around the tube
inline constexpr int kTubeRings = 150;             ///< vertex rings along the tube
inline constexpr double kTubeLengthMm = 150.0;     ///< nominal centreline length, mm
inline constexpr double kTubeMeanRadiusMm = 10.0;  ///< mean tube radius, mm

/// Patch UV of the planar point (x, y) in mm, x in [-40, 40], y in [-30, 30]; one chart with
/// isotropic texels (80 mm span [g, 1 - g] in u, v centred).
Float2 patchUv(double xMm, double yMm);

/// Liver UV of cube face `face` (0..5) at face parameters (s, t) in [0, 1]^2: six square charts
/// in a 3 x 2 layout with gutters.
Float2 liverUv(int face, double s, double t);

/// Point on the cube [-1, 1]^3 of face `face` at face parameters (s, t); (s, t) may lie slightly
/// outside [0, 1] (gutters extrapolate the face). Face axes satisfy u x v = outward normal.
Eigen::Vector3d cubeFacePoint(int face, double s, double t);

/// Cube-to-sphere map with nearly uniform cells (x' = x sqrt(1 - y^2/2 - z^2/2 + y^2 z^2 / 3)).
Eigen::Vector3d cubeToSphere(const Eigen::Vector3d& c);

/// Tube UV at `aroundFraction` (0..1 around, 1 = the seam again) and `alongFraction` (0..1 along):
/// isotropic texels for the mean radius, u centred, v spanning [g, 1 - g].
Float2 tubeUv(double aroundFraction, double alongFraction);

/// Point in pattern space (mm) seen by texture coordinate (u, v) of `kind`; gutter texels
/// extrapolate the nearest chart so bilinear filtering and mip-maps stay continuous.
Eigen::Vector3d patternPoint(MeshKind kind, double u, double v);

}  // namespace tissue::datagen
