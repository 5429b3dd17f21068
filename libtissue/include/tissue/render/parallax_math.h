#pragma once
/// \file
/// The GL-free arithmetic of the layered-parallax method (Oat 2006, as in Norberg 2010 §2.2):
/// the transmission vector and the inner layer's lookup offset (eq. 15-18), generalised by
/// Snell's law for a relative refractive index, and the Poisson disc of the lightmap blur
/// (§2.2.2, §3.2). shaders/parallax/ computes the same on the GPU; tests check this one
/// against Snell's law analytically.

#include <cstdint>
#include <vector>

#include "tissue/core/types.h"

namespace tissue::render {

/// Where the view ray meets an inner layer, in the tangent frame of the shading point
/// (x along the tangent T, y along the bitangent B, z along the geometric normal; orthonormal,
/// so lengths are mm).
struct TransmissionLookup {
  Float3 direction;      ///< unit transmission vector (z < 0: into the surface)
  Float2 offsetMm;       ///< eq. 18's s (T_x, T_y): tangent-plane offset to the lookup, mm
  float transmissionMm;  ///< eq. 17's s: distance along `direction` to the layer, mm
};

/// The transmission vector and the inner layer's offset at `depthMm` below the surface.
/// \param viewTangent    unit vector from the surface point toward the eye, tangent frame
/// \param normalTangent  unit shading normal (from the normal map), tangent frame
/// \param relativeIndex  n_inside / n_outside (unitless, >= 1; 1 is Oat's eq. 15-16 exactly)
/// \param depthMm        d of eq. 17, mm
/// \param maxTransmissionMm  s is clamped here (grazing views), mm
/// Eq. 15 reflects -V about N, eq. 16 mirrors the result below the tangent plane; the
/// tangential part is then divided by the relative index and z renormalised (Snell: sin theta_t
/// = sin theta_i / n), so with the geometric normal the offset is d tan(theta_t).
TransmissionLookup transmissionLookup(Float3 viewTangent, Float3 normalTangent, float relativeIndex,
                                      float depthMm, float maxTransmissionMm = 1e30f);

/// `count` points (even, 2..64) in the unit disc with a minimum spacing (Cook 1985): Mitchell's
/// best-candidate dart throwing from a fixed seed, in +-p pairs so their mean is exactly the
/// centre (a blur by them does not shift the map). Deterministic.
std::vector<Float2> poissonDisc(int count, std::uint32_t seed = 1u);

/// The radius of one of `passes` Poisson-disc passes that together blur about as much as one
/// pass of `totalRadiusMm` (variances add: r / sqrt(passes); Norberg §3.2 multipass), mm.
float poissonPassRadiusMm(float totalRadiusMm, int passes);

}  // namespace tissue::render
