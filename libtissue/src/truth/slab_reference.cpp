// Single scattering of a flat layered half-space in closed form (slab_reference.h).
#include "tissue/truth/slab_reference.h"

#include <cmath>
#include <numbers>

#include "interface_math.h"
#include "tissue/optics/fresnel.h"
#include "tissue/optics/phase_function.h"

namespace tissue::truth {

Rgb layeredSlabSingleScattering(const TruthMaterial& material, Float3 toEye, Float3 toLight,
                                Rgb lightRadiance) {
  Rgb out{0.0, 0.0, 0.0};
  if (material.layers.empty()) return out;
  const glm::dvec3 n(0.0, 0.0, 1.0);
  const glm::dvec3 v = glm::normalize(glm::dvec3(toEye.x, toEye.y, toEye.z));
  const glm::dvec3 l = glm::normalize(glm::dvec3(toLight.x, toLight.y, toLight.z));
  if (v.z <= 0.0 || l.z <= 0.0) return out;
  const double nA = material.ambientN, nT = material.layers.front().n;
  const optics::FresnelResult fv = optics::fresnelReflectance(nA, nT, v.z);
  const optics::FresnelResult fl = optics::fresnelReflectance(nA, nT, l.z);
  if (fv.reflectance >= 1.0 || fl.reflectance >= 1.0) return out;
  // Travel directions inside: the view ray's (reversed: light leaves along -dv) and the light's.
  const glm::dvec3 dv = detail::refract(-v, n, nA / nT, v.z, fv.cosTransmitted);
  const glm::dvec3 dl = detail::refract(-l, n, nA / nT, l.z, fl.cosTransmitted);
  const double muV = -dv.z, muL = -dl.z;
  const double c = 1.0 / muL + 1.0 / muV;
  const double cosTheta = glm::dot(dl, -dv);
  for (int band = 0; band < kBands; ++band) {
    const auto b = static_cast<std::size_t>(band);
    double tau = 0.0, sum = 0.0;
    for (const TruthLayer& layer : material.layers) {
      if (!layer.sigmaA || !layer.sigmaS) return Rgb{};
      const double sigmaS = (*layer.sigmaS)[b], sigmaT = (*layer.sigmaA)[b] + sigmaS;
      const double thickness = layer.thicknessMm;
      if (sigmaT > 0.0) {
        const double slab = std::isfinite(thickness) ? 1.0 - std::exp(-c * sigmaT * thickness) : 1.0;
        sum += sigmaS * optics::henyeyGreenstein(cosTheta, layer.g[b]) / muV * std::exp(-c * tau) * slab /
               (c * sigmaT);
      }
      tau += sigmaT * thickness;
      if (!std::isfinite(tau)) break;
    }
    const double irradiance = std::numbers::pi * lightRadiance[b];
    const double inside = (1.0 - fl.reflectance) * irradiance * l.z / muL;
    out[b] = (1.0 - fv.reflectance) * (nA / nT) * (nA / nT) * inside * sum;
  }
  return out;
}

}  // namespace tissue::truth
