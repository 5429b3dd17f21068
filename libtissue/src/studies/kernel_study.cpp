// Freude 2014's kernel comparison (kernel_study.h).
#include "tissue/studies/kernel_study.h"

#include <ctime>

#include "json_text.h"
#include "tissue/core/stopwatch.h"
#include "tissue/optics/ground_truth_kernel.h"

namespace tissue::studies {
namespace {

using optics::KernelModel;

using ExactImages = std::map<std::string, std::pair<optics::SignalImage, optics::ImageRgb>>;

/// Builds with `build`, timing wall and process CPU time (ms).
template <class Build>
auto timedBuild(double& wallMs, double& cpuMs, Build build) {
  Stopwatch watch;
  const std::clock_t cpuStart = std::clock();
  auto kernel = build();
  wallMs = watch.elapsedMs();
  cpuMs = 1000.0 * static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;
  return kernel;
}

nlohmann::json tapsJson(const std::vector<optics::KernelTap>& taps) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& t : taps)
    out.push_back({t.weight.x, t.weight.y, t.weight.z, t.offsetMm});
  return out;
}

Result<KernelRun> runSpec(const optics::GroundTruthKernel& truth, const KernelSpec& spec,
                          const ExactImages& exact) {
  optics::KernelSettings s = spec.settings;
  if (spec.model == KernelModel::Manual) {
    auto p = optics::manualParameters(truth.name);
    if (!p) return p.error();
    s.manual = *p;
  }
  KernelRun run;  // timed from the radial profile: the grid, the model and the taps
  auto kernel = timedBuild(run.buildMs, run.buildCpuMs,
                           [&] { return optics::buildKernel(truth.profile, spec.model, s); });
  if (!kernel) return kernel.error();
  run.kernelRms = optics::kernelSpaceRms(truth, *kernel);
  for (const auto& [name, pair] : exact)
    run.imageRms[name] = optics::rmsDifference(pair.second, optics::convolveSeparable(*kernel, pair.first));
  const auto h = static_cast<std::size_t>(truth.halfCells);
  for (std::size_t x = 0; x < static_cast<std::size_t>(truth.size()); ++x) {
    double a = 0;
    for (const auto& c : kernel->components)
      a += static_cast<double>(c.sign.x) * c.dense[0][h] * c.dense[0][x];
    run.sliceRed.push_back(a);
  }
  return run;
}

}  // namespace

std::vector<KernelSpec> rankOneSpecs() {
  optics::KernelSettings plain, normalised;
  normalised.normalizeEnergy = true;
  return {{"SVD1", KernelModel::Svd, plain},
          {"SVD1 N.", KernelModel::Svd, normalised},
          {"Pre-int.", KernelModel::PreIntegrated, plain},
          {"Guided k=1", KernelModel::Guided, plain},
          {"Manual", KernelModel::Manual, plain},
          {"d'Eon 1", KernelModel::Deon, plain},
          {"Jimenez", KernelModel::Jimenez, plain}};
}

const std::vector<std::pair<std::string, optics::TestSignal>>& kernelStudySignals() {
  static const std::vector<std::pair<std::string, optics::TestSignal>> signals{
      {"edge", optics::TestSignal::VerticalEdge},
      {"circle+squares", optics::TestSignal::CircleAndSquares},
      {"shaded patch", optics::TestSignal::ShadedPatch}};
  return signals;
}

Result<KernelStudy> studyKernels(const optics::ScatteringMaterial& material) {
  auto profile = optics::groundTruthProfile(material);
  if (!profile) return profile.error();
  auto truth = optics::groundTruthKernel(*profile, 100);
  if (!truth) return truth.error();
  KernelStudy study{material.name, truth->cellMm, truth->halfCells, {}, {}};
  for (int x = 0; x < truth->size(); ++x)
    study.truthSliceRed.push_back(truth->at(0, truth->halfCells, x));
  ExactImages exact;
  for (const auto& [label, signal] : kernelStudySignals()) {
    auto img = optics::makeTestSignal(signal, 256);
    auto conv = optics::convolveExact(*truth, img);
    exact[label] = {std::move(img), std::move(conv)};
  }
  std::vector<KernelSpec> specs = rankOneSpecs();
  for (int k = 1; k <= 6; ++k) {
    optics::KernelSettings s;
    s.rank = k;
    specs.push_back({"SVD " + std::to_string(k), KernelModel::Svd, s});
    specs.push_back({"d'Eon " + std::to_string(k), KernelModel::Deon, s});
  }
  for (const auto& spec : specs) {
    auto run = runSpec(*truth, spec, exact);
    if (!run) return Error{study.name + ", " + spec.label + ": " + run.error().message};
    study.runs[spec.label] = std::move(*run);
  }
  return study;
}

Result<KernelMeasurement> measureKernel(const optics::ScatteringMaterial& material, optics::KernelModel model,
                                        const optics::KernelSettings& settings) {
  KernelMeasurement m{.material = material.name};
  Result<optics::SeparableKernel> kernel = Error{"not built"};
  double cpuMs = 0;
  for (int round = 0; round < 2; ++round) {  // build_first_ms, then build_ms
    kernel = timedBuild(round ? m.buildMs : m.buildFirstMs, round ? m.buildCpuMs : cpuMs,
                        [&] { return optics::buildKernel(material, model, settings); });
    if (!kernel) return kernel.error();
  }
  m.kernel = std::move(*kernel);
  auto profile = optics::groundTruthProfile(material);
  if (!profile) return profile.error();
  auto truth = optics::groundTruthKernel(*profile, settings.gridHalfCells);
  if (!truth) return truth.error();
  m.kernelRms = optics::kernelSpaceRms(*truth, m.kernel);
  m.imageRms = optics::imageSpaceRms(*truth, m.kernel, optics::TestSignal::CircleAndSquares);
  m.energy = optics::kernelEnergy(m.kernel);
  m.gridCellMm = truth->cellMm;
  m.kernelHalfWidthMm = profile->kernelHalfWidthMm;
  return m;
}

std::string kernelMeasurementJson(const KernelMeasurement& m) {
  nlohmann::json out{{"material", m.material},
                     {"model", std::string(optics::kernelModelName(m.kernel.model))},
                     {"rank", m.kernel.components.size()},
                     {"taps", tapsJson(m.kernel.taps())},
                     {"build_ms", m.buildMs},
                     {"build_cpu_ms", m.buildCpuMs},
                     {"build_first_ms", m.buildFirstMs},
                     {"kernel_rms", m.kernelRms},
                     {"image_rms", m.imageRms},
                     {"energy", m.energy},
                     {"grid_cell_mm", m.gridCellMm},
                     {"kernel_half_width_mm", m.kernelHalfWidthMm}};
  if (m.kernel.components.size() > 1) {
    nlohmann::json comps = nlohmann::json::array();
    for (const auto& c : m.kernel.components)
      comps.push_back({{"sign", {c.sign.x, c.sign.y, c.sign.z}}, {"taps", tapsJson(c.taps)}});
    out["components"] = comps;
  }
  out["units"] =
      "taps: [w_R, w_G, w_B, offset_mm]; offsets in mm on the surface (scale by pixels per mm, from "
      "sssWidth); "
      "kernel_rms over the (2h+1)^2 ground-truth grid normalised to 1; image_rms on the circle-and-squares "
      "signal "
      "in [0, 1], 256^2 pixels of grid_cell_mm";
  return detail::jsonText(out);
}

}  // namespace tissue::studies
