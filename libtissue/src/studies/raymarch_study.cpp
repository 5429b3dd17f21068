// Where ray-marched subsurface texture mapping fails, on the CPU model.
#include "tissue/studies/raymarch_study.h"

#include <algorithm>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <vector>

#include "tissue/studies/raymarch_scene.h"

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

Result<RayMarchStudyResult> runRayMarchStudy(
    const std::function<scene::OrganSource(const std::string&)>& organSource,
    const RayMarchStudyConfig& config, bool images) {
  RayMarchStudyResult out;
  nlohmann::json cases = nlohmann::json::array();
  const std::string few = std::to_string(config.fewSamples);
  Table table{{"case", "plane", "plane grazing", "plane frontal", few + " samples", few + " grazing",
               few + " frontal", "what"},
              {}};
  for (const RayMarchStudyCase& c : kRayMarchStudyCases) {
    const std::string name = c.name;
    auto scene = loadRayMarchScene(organSource(c.mesh), float(config.width) / float(config.height), true);
    if (!scene) return Error{name + ": " + scene.error().message};
    if (c.pokeDepthMm > 0.0f)
      if (auto poked = pokeScene(*scene, 0.02, c.pokeDepthMm); !poked)
        return Error{name + ": " + poked.error().message};
    RayMarchStudy r = studyRayMarch(meshView(*scene), scene->material.stack, scene->lights,
                                    pinholeOf(scene->camera), config);
    cases.push_back({{"case", name},
                     {"what", c.what},
                     {"plane_rms", r.planes.all},
                     {"plane_rms_grazing", r.planes.grazing},
                     {"plane_rms_frontal", r.planes.frontal},
                     {"samples10_rms", r.few.all},
                     {"samples10_rms_grazing", r.few.grazing},
                     {"samples10_rms_frontal", r.few.frontal}});
    table.rows.push_back({name, fixed(r.planes.all, 4), fixed(r.planes.grazing, 4),
                          fixed(r.planes.frontal, 4), fixed(r.few.all, 4), fixed(r.few.grazing, 4),
                          fixed(r.few.frontal, 4), c.what});
    if (images) {
      const std::string stem = "raymarch_fail_" + name;
      auto& list = out.output.report.images;
      list.push_back({stem + "_plane_error_x8.png", differenceImage(r.planesImage, r.reference)});
      list.push_back({stem + "_reference.png", std::move(r.reference)});
      list.push_back({stem + "_10samples.png", std::move(r.fewImage)});
    }
    out.cases.push_back({name, c.what, r.planes, r.few});
  }
  const nlohmann::json json{{"width", config.width},
                            {"height", config.height},
                            {"reference_samples", config.referenceSamples},
                            {"cases", cases}};
  out.output.json = json.dump(2);
  out.output.summary = markdownTable(table);
  out.output.report.add(
      "raymarch_study.md",
      "# Where ray-marched subsurface texture mapping fails\n\nDisplay RMS (0..1) against the mesh-entry "
      "march (" +
          std::to_string(config.referenceSamples) + " samples), " + std::to_string(config.width) + " x " +
          std::to_string(config.height) + " pixels: the plane approximation (same samples) and " + few +
          " jittered samples, over all covered pixels, the grazing ones (N.V < 0.3) and the frontal ones "
          "(N.V >= 0.7); -1: no pixel in the band.\n\n" +
          out.output.summary);
  out.output.report.add("raymarch_study.csv", csvTable(table));
  out.output.report.add("raymarch_study.json", out.output.json + "\n");
  return out;
}

}  // namespace tissue::studies
