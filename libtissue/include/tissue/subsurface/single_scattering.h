#pragma once
/// \file
/// Single scattering in a layered material by ray marching (François et al. 2006, eq. 1-5,
/// Algorithms 1 and 2; Norberg 2010, §2.1 and §3.1), on the CPU. Two ways to find where the
/// light enters the tissue on its way to a sample point M:
/// - plane mode (`mesh == nullptr`): through the plane interpolated between P's tangent plane
///   and its fitted local plane (eq. 9-10, 14-15), exactly as the GPU shader does;
/// - mesh mode: the first crossing of the ray M -> light with the actual (deformed) mesh, and
///   the march stops where the viewing ray leaves the mesh.
/// Both estimate the per-layer distances with Norberg's eq. 13-14 (with the max(., 0) fix).
/// Lengths in mm, coefficients in mm^-1, radiance in the light's units.

#include <span>

#include "tissue/core/types.h"
#include "tissue/subsurface/layer_stack.h"
#include "tissue/subsurface/triangle_bvh.h"

namespace tissue::subsurface {

/// A point light without distance falloff (as the renderer's).
struct Light {
  Float3 positionMm{150.0f, 200.0f, 250.0f};  ///< mm
  Float3 radiance{2.5f, 2.4f, 2.3f};          ///< linear RGB, unitless radiance scale
};

/// Everything the march needs at the visible surface point P (what a fragment shader gets).
struct ShadingPoint {
  Float3 position;   ///< P, mm
  Float3 toEye;      ///< omega_out, unit, from P towards the eye
  Float3 normal;     ///< N_P, unit interpolated vertex normal (the tangent plane at P)
  Float4 plane;      ///< interpolated fitted plane (N_S, d): N_S (normalised here), d in mm (eq. 14)
  Float3 tangent;    ///< T, unit, direction of increasing u
  Float3 bitangent;  ///< B, unit, direction of increasing v
  Float2 uv;         ///< texture coordinates at P, unitless
  float uvPerMm = 1.0f / 80.0f;  ///< texture-coordinate units per mm along T and B
};

/// Ray-march parameters (shared with the shader's uniforms).
struct MarchSettings {
  int samples = 50;         ///< samples along P..M_max (Algorithm 1's numberofsamples)
  float depthMaxMm = 3.0f;  ///< Depth_max of eq. 15, mm, measured along N_S
  float attenuationThreshold =
      1e-3f;                  ///< stop once exp(-tau_PM) * max reduced light falls below it (0: never)
  float minCosView = 0.1f;    ///< lower clamp of N_S . omega_out in eq. 15 (grazing views)
  float maxLengthMm = 1e30f;  ///< mm, upper bound of |PM_max| (adaptive quality shortens it)
};

/// The result for one point.
struct MarchResult {
  Float3 radiance;      ///< single-scattered radiance leaving P towards the eye, light units
  int samplesUsed = 0;  ///< samples evaluated before the march stopped
};

/// Evaluates eq. 5 with `settings.samples` samples at t_i = (i + jitter) dt, dt = |PM_max| / n,
/// for every light in `lights`. `jitter` in [0, 1) is the per-pixel offset of noisy sampling
/// (Norberg §3.1.2); 0.5 is the midpoint rule. With `mesh` the light's entry point is found on
/// the mesh (mesh mode), else through the interpolated planes (plane mode).
MarchResult marchSingleScattering(const ShadingPoint& point, const LayerStack& stack,
                                  std::span<const Light> lights, const MarchSettings& settings, float jitter,
                                  const TriangleBvh* mesh = nullptr);

/// The per-pixel noise of noisy sampling: a PCG hash of the pixel (x, y) and a frame seed, as a
/// uniform number in [0, 1). The shader computes the same bits (shaders/raymarch/march.glsl).
float pixelJitter(unsigned x, unsigned y, unsigned seed = 0);

/// Adaptive quality (docs/DECISIONS.md): per point, march only as deep as light still returns
/// from, and only as finely as the layers and the pixel need.
/// - Length: light scattered at distance t along the viewing ray has crossed at least
///   sigma_min t (1 + cos) optical depth (down and back up); beyond transmittance `cutoff` the
///   march stops (never beyond eq. 15's M_max).
/// - Count: enough that the depth step stays below `depthResolutionMm` and the sideways step
///   in texture space below the larger of a texel and the pixel's footprint `pixelMm` (mm).
struct AdaptiveSettings {
  int minSamples = 4;               ///< floor
  int maxSamples = 100;             ///< ceiling (the full-quality count)
  float depthResolutionMm = 0.06f;  ///< wanted depth step, mm
  float texelsPerStep = 1.5f;       ///< wanted sideways step, texels (or pixels, whichever is larger)
  float cutoff = 0.03f;             ///< round-trip transmittance below which the march stops, 0..1
};

/// The adaptive choice at one point.
struct AdaptiveChoice {
  int samples = 0;        ///< samples to march
  float lengthMm = 0.0f;  ///< |PM_max| to march over, mm (set MarchSettings::maxLengthMm to it)
};

/// The adaptive sample count and march length at `point`, whose pixel covers `pixelMm` mm.
AdaptiveChoice adaptiveMarch(const ShadingPoint& point, const LayerStack& stack, const MarchSettings& march,
                             const AdaptiveSettings& adaptive, float pixelMm);

}  // namespace tissue::subsurface
