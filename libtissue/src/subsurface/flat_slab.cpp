// Closed-form single scattering of a flat layered slab (François et al. 2006 eq. 3).
#include "tissue/subsurface/flat_slab.h"

#include <algorithm>
#include <cmath>

#include "tissue/optics/schlick_phase.h"

namespace tissue::subsurface {

Float3 flatSlabSingleScattering(std::span<const LayerCoefficients> layers,
                                std::span<const float> boundariesMm, Float3 toEye, Float3 toLight,
                                float depthMaxMm) {
  const double muV = toEye.z, muL = toLight.z;
  const double c = 1.0 / muL + 1.0 / muV;  // optical depth per unit depth, light path plus view path
  const double cosT = -(toEye.x * toLight.x + toEye.y * toLight.y + toEye.z * toLight.z);
  double out[3] = {0.0, 0.0, 0.0};
  for (int ch = 0; ch < 3; ++ch) {
    double tauAbove = 0.0;  // optical depth of the layers above, along the normal
    double top = 0.0;
    for (std::size_t j = 0; j < layers.size() && top < double(depthMaxMm); ++j) {
      const double bottom =
          std::min<double>(j < boundariesMm.size() ? double(boundariesMm[j]) : 1e30, depthMaxMm);
      const LayerCoefficients& l = layers[j];
      const double st = ch == 0 ? l.sigma_t.x : (ch == 1 ? l.sigma_t.y : l.sigma_t.z);
      const double ss = ch == 0 ? l.sigma_s.x : (ch == 1 ? l.sigma_s.y : l.sigma_s.z);
      const double p = optics::schlickPhase(cosT, optics::schlickKFromG(l.g));
      if (bottom > top) {
        // Integral over depth z in [top, bottom] of sigma_s p exp(-c tau(z)) dz / mu_v, where
        // dz / mu_v is the step along the viewing ray.
        out[ch] +=
            ss * p / muV * std::exp(-c * tauAbove) * (1.0 - std::exp(-c * st * (bottom - top))) / (c * st);
        tauAbove += st * (bottom - top);
      }
      top = std::max(top, bottom);
    }
  }
  return {float(out[0]), float(out[1]), float(out[2])};
}

}  // namespace tissue::subsurface
