// Where ray-marched subsurface texture mapping fails, on the CPU model.
#include "tissue/studies/raymarch_study.h"

#include <algorithm>
#include <cstdlib>
#include <vector>

namespace tissue::studies {

double displayRmsWhere(const Image8& a, const Image8& b, const subsurface::RadianceImage& ref, float lo,
                       float hi) {
  std::vector<std::uint8_t> mask(ref.covered.size(), 0);
  std::size_t n = 0;
  for (std::size_t i = 0; i < mask.size(); ++i)
    if (ref.covered[i] && ref.viewCos[i] >= lo && ref.viewCos[i] < hi) mask[i] = 1, ++n;
  return n ? subsurface::displayRms(a, b, mask) : -1.0;
}

Image8 differenceImage(const Image8& a, const Image8& b, int gain) {
  Image8 out(a.width, a.height, 4);
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      for (int c = 0; c < 3; ++c)
        out.at(x, y)[c] = std::uint8_t(std::min(255, gain * std::abs(a.at(x, y)[c] - b.at(x, y)[c])));
      out.at(x, y)[3] = 255;
    }
  return out;
}

RayMarchStudy studyRayMarch(const subsurface::MeshView& mesh, const subsurface::LayerStack& stack,
                            std::span<const subsurface::Light> lights,
                            const subsurface::PinholeCamera& camera, const RayMarchStudyConfig& config) {
  auto image = [&](subsurface::EntryMode entry, int samples, bool jitter) {
    subsurface::CpuImageSettings s;
    s.width = config.width;
    s.height = config.height;
    s.entry = entry;
    s.jitter = jitter;
    s.march.samples = samples;
    s.march.attenuationThreshold = 0.0f;
    return subsurface::renderSingleScatteringCpu(mesh, stack, lights, camera, s);
  };
  const auto ref = image(subsurface::EntryMode::Mesh, config.referenceSamples, false);
  const auto planes = image(subsurface::EntryMode::Planes, config.referenceSamples, false);
  const auto few = image(subsurface::EntryMode::Planes, config.fewSamples, true);
  RayMarchStudy out;
  out.reference = subsurface::toDisplay(ref, config.radianceScale, config.background);
  out.planesImage = subsurface::toDisplay(planes, config.radianceScale, config.background);
  out.fewImage = subsurface::toDisplay(few, config.radianceScale, config.background);
  auto errors = [&](const Image8& a) {
    return RayMarchErrors{subsurface::displayRms(a, out.reference, ref.covered),
                          displayRmsWhere(a, out.reference, ref, -1.0f, 0.3f),
                          displayRmsWhere(a, out.reference, ref, 0.7f, 2.0f)};
  };
  out.planes = errors(out.planesImage);
  out.few = errors(out.fewImage);
  return out;
}

}  // namespace tissue::studies
