#pragma once
/// \file
/// Where layered parallax (Oat 2006; Norberg 2010 §2.2) fails, in numbers. The method looks the
/// inner layer up at the tangent-plane offset of eq. 15-18 (layers "flat and parallel in tangent
/// space"); the truth is the refracted view ray intersected with the actual inner layer, the
/// surface pushed in by the depth along -N. Per view angle: the distance (mm, on the outer
/// surface) between the texel the method reads and the true one, and the fraction of rays that
/// leave the surface before reaching the layer (the method still shows a layer there). GL-free
/// (the method's arithmetic is render/parallax_math.h's). Lengths in mm, angles in degrees.

#include <array>
#include <string>
#include <vector>

#include "tissue/core/types.h"
#include "tissue/render/shading.h"

namespace tissue::studies {

/// A closed or open triangle mesh the study samples.
struct ParallaxSurface {
  std::string name, what;                  ///< label and description for the reports
  std::vector<Float3> positions, normals;  ///< mm, unit vertex normals
  std::vector<Triangle> triangles;         ///< counter-clockwise seen from outside
  /// mm, > 0 per axis: only points with |x|, |y| or |z| below it are sampled (away from open
  /// borders and lat-long poles); 0: no limit on that axis.
  std::array<double, 3> sampleBoxMm{0.0, 0.0, 0.0};
};

/// A grid of `quads` x `quads` quads, 300 mm square at z = 0 (+z out), sampled in its middle
/// 200 mm (no ray from there reaches the border): the control, where the method's assumption holds.
ParallaxSurface parallaxPlane(int quads);

/// A latitude-longitude sphere of `radiusMm` (closed: the pole rows collapse to points) with
/// `quads` x `quads` quads, sampled away from its poles (|z| < 0.95 r).
ParallaxSurface parallaxSphere(double radiusMm, int quads);

/// One (surface, depth, index, angle) cell of the study.
struct ParallaxCell {
  float viewAngleDeg = 0.0f;  ///< degrees from the normal
  int samples = 0;            ///< points sampled (the lookup fell on the surface or not)
  int reached = 0;            ///< rays that reach the inner layer before leaving the surface
  int misses = 0;             ///< rays that leave the outer surface first
  double missFraction = 0.0;  ///< misses / samples (0 without samples)
  /// Over the rays that reached the layer; -1 when none did.
  double meanErrorMm = -1.0, p95ErrorMm = -1.0, maxErrorMm = -1.0;
  double meanParallaxOffsetMm = -1.0;  ///< mm from the shading point to the texel the method reads
  double meanTrueOffsetMm = -1.0;      ///< mm from the shading point to the true texel
};

/// One surface at one depth and relative index, over the view angles.
struct ParallaxRow {
  std::string surface, what;
  float depthMm = 0.0f;
  float refractiveIndex = 1.0f;
  std::vector<ParallaxCell> cells;  ///< one per view angle, in the config's order
};

struct ParallaxStudyConfig {
  std::vector<float> depthsMm{1.0f, 3.0f};           ///< inner layer depths, mm
  std::vector<float> refractiveIndices{1.0f, 1.4f};  ///< n_inside / n_outside, unitless
  std::vector<float> viewAnglesDeg{0.0f, 30.0f, 45.0f, 60.0f, 75.0f, 85.0f};  ///< from the normal
  int samplePoints = 1500;  ///< surface points per surface and angle (one per stride of triangles)
  /// mm, eq. 17's clamp of the transmission distance (the renderer's default).
  float maxTransmissionMm = render::ParallaxSettings{}.maxTransmissionMm;
};

/// The cell of one view angle: the inner layer is `surface` pushed in by `depthMm` along its
/// vertex normals. Deterministic (fixed hashed sample points and azimuths).
ParallaxCell measureParallaxLookup(const ParallaxSurface& surface, float depthMm, float refractiveIndex,
                                   float viewAngleDeg, int samplePoints, float maxTransmissionMm);

/// Every surface x depth x index row (in that order), each over the config's view angles.
std::vector<ParallaxRow> studyParallax(const std::vector<ParallaxSurface>& surfaces,
                                       const ParallaxStudyConfig& config = {});

}  // namespace tissue::studies
