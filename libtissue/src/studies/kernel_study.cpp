// Freude 2014's kernel comparison (kernel_study.h).
#include "tissue/studies/kernel_study.h"

#include <ctime>

#include "tissue/core/stopwatch.h"
#include "tissue/optics/ground_truth_kernel.h"

namespace tissue::studies {
namespace {

using optics::KernelModel;

using ExactImages = std::map<std::string, std::pair<optics::SignalImage, optics::ImageRgb>>;

Result<KernelRun> runSpec(const optics::GroundTruthKernel& truth, const KernelSpec& spec,
                          const ExactImages& exact) {
  optics::KernelSettings s = spec.settings;
  if (spec.model == KernelModel::Manual) {
    auto p = optics::manualParameters(truth.name);
    if (!p) return p.error();
    s.manual = *p;
  }
  KernelRun run;
  Stopwatch watch;  // from the radial profile: the grid, the model and the taps
  const std::clock_t cpuStart = std::clock();
  auto kernel = optics::buildKernel(truth.profile, spec.model, s);
  run.buildMs = watch.elapsedMs();
  run.buildCpuMs = 1000.0 * static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;
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

}  // namespace tissue::studies
