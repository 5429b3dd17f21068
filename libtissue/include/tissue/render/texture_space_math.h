#pragma once
/// \file
/// The GL-free maths of texture-space diffusion (d'Eon, Luebke and Enderton 2007) and of the
/// three irradiance-map optimisations of Jimenez and Gutierrez 2008 (§3 culled, §4 depth-based
/// size, §5 clipped). The shaders do the same arithmetic per vertex or texel; the tests check it
/// here on known inputs. Lengths are mm, the map size is texels.

#include <array>
#include <span>
#include <vector>

#include "tissue/core/types.h"

namespace tissue::render {

/// A 4x4 matrix, column-major (OpenGL's layout): m[col * 4 + row].
using Mat4 = std::array<float, 16>;

/// cos(105 degrees): the culled irradiance map stores alpha = 1 where dot(N_eye, V) is at least
/// this (Jimenez et al. §3, Listing 2), extending back-face culling 15 degrees past the profile.
inline constexpr float kCullCosine = -0.25881904510252074f;

/// Jimenez et al. eq. 3: s = min(d_ref / d, 1), the fraction of the maximum map size used.
/// \param nearestDistanceMm  d, mm: camera to the nearest corner of the object's bounding box
/// \param referenceDistanceMm d_ref, mm: the distance at which the map has its full size
float irradianceMapScale(float nearestDistanceMm, float referenceDistanceMm);

/// Jimenez et al. eq. 4: T = s T_max texels, rounded up, never below `minSize` nor above T_max.
int irradianceMapSize(float scale, int maxSize, int minSize = 16);

/// d of Jimenez et al. Fig. 4: distance (mm) from `eye` to the nearest of the eight corners of
/// the box [lo, hi] (mm).
float nearestBoxCornerDistance(Float3 eye, Float3 lo, Float3 hi);

/// Jimenez et al. eq. 5-6: the six frustum planes Pi_clip = (+-1, 0, 0, D), (0, +-1, 0, D),
/// (0, 0, +-1, D) moved to eye space, Pi_eye = P^T Pi_clip, for the projection `projection`
/// (eye to clip). A point p (eye space, mm) is inside a plane when dot(Pi, (p, 1)) >= 0.
/// \param clipD D of eq. 5; 1 is the exact frustum, more keeps a margin (the paper uses 1)
std::array<Float4, 6> eyeSpaceFrustumPlanes(const Mat4& projection, float clipD = 1.0f);

/// True when the eye-space point `p` (mm) is on the inner side of all six planes.
bool insideFrustum(const std::array<Float4, 6>& planes, Float3 p);

/// The stretch of a UV map over one triangle: |dP/du| and |dP/dv|, mm per UV unit (d'Eon et al.
/// §3.2's stretch correction; the shader gets the same from screen-space derivatives of the
/// world position while rasterising in UV space). A Gaussian of standard deviation sigma mm
/// spans sigma / |dP/du| UV units along u.
/// \param p   the triangle's corners, mm
/// \param uv  the corners' texture coordinates
Float2 uvStretch(const std::array<Float3, 3>& p, const std::array<Float2, 3>& uv);

/// The density of a UV map: sqrt(UV area / surface area), UV units per mm (times the map size:
/// texels per mm, for d_ref of eq. 3). 0 for a mesh without area.
float uvDensity(std::span<const Float3> positionsMm, std::span<const Float2> uvs,
                std::span<const Triangle> triangles);

/// One Gaussian of a sum-of-Gaussians diffusion profile: R(r) = sum_i w_i G(v_i, r),
/// G(v, r) = exp(-r^2 / (2 v)) / (2 pi v) (d'Eon et al.; Jimenez et al. eq. 2).
struct ProfileGaussian {
  float varianceMm2 = 0.0f;  ///< v_i, mm^2
  Float3 weight;             ///< w_i per RGB channel, unitless
};

/// R(r) per channel, mm^-2, at `rMm` mm.
Float3 evaluateGaussianSum(const std::vector<ProfileGaussian>& gaussians, float rMm);

/// The variances each separable blur adds: d'Eon blurs the previous result again, since
/// G(v1) * G(v2) = G(v1 + v2), so step i adds v_i - v_{i-1} (v_{-1} = 0). Variances must increase.
std::vector<float> incrementalVariances(const std::vector<ProfileGaussian>& gaussians);

/// One tap of a 1D Gaussian blur: offset in standard deviations and its weight.
struct BlurTap {
  float offsetSigma = 0.0f;  ///< unitless, in standard deviations of the blur
  float weight = 0.0f;       ///< unitless; the taps' weights sum to 1
};

/// 2 * halfTaps + 1 taps evenly over [-3 sigma, 3 sigma], weights exp(-x^2 / 2) normalised
/// (d'Eon's 7-tap blur for halfTaps = 3).
std::vector<BlurTap> gaussianBlurTaps(int halfTaps);

}  // namespace tissue::render
