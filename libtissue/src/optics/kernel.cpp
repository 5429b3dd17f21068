// buildKernel: validate, run the model (one file each), sample the taps (kernel.h).
#include "tissue/optics/kernel.h"

#include <algorithm>
#include <cctype>

#include "kernel_models.h"
#include "tissue/optics/kernel_gaussians.h"
#include "tissue/optics/kernel_jimenez.h"

namespace tissue::optics {
namespace {

constexpr KernelModel kModels[] = {KernelModel::Svd,    KernelModel::PreIntegrated, KernelModel::Guided,
                                   KernelModel::Manual, KernelModel::Deon,          KernelModel::Jimenez};

Result<void> checkSettings(KernelModel model, const KernelSettings& s, int gridSize) {
  const std::string where = "kernel model '" + std::string(kernelModelName(model)) + "': ";
  if (s.taps < 3 || (s.taps % 2 == 0 && s.taps < gridSize))
    return Error{where + std::to_string(s.taps) + " taps; use an odd count >= 3 (centre plus pairs)"};
  if (s.rank < 1 || s.rank > 8)
    return Error{where + "rank " + std::to_string(s.rank) + " is out of range; use 1..8"};
  if (model == KernelModel::Manual) {
    for (int c = 0; c < kChannels; ++c) {
      const auto ch = static_cast<std::size_t>(c);
      if (!(s.manual.sigmaNearMm[ch] > 0.0) || !(s.manual.sigmaFarMm[ch] > 0.0))
        return Error{where +
                     "needs both Gaussian widths > 0 mm per channel (manualParameters gives Freude's "
                     "Table A.1 for Apple, Ketchup, Marble, Skin1, Wholemilk)"};
    }
    if (!(s.manual.nearWeight >= 0.0 && s.manual.nearWeight <= 1.0))
      return Error{where + "the near weight w must be in [0, 1]"};
  }
  return {};
}

Result<std::vector<detail::DenseComponent>> denseComponents(const GroundTruthKernel& truth, KernelModel model,
                                                            const KernelSettings& s) {
  switch (model) {
    case KernelModel::Svd:
      return detail::svdComponents(truth, s.rank, s.normalizeEnergy);
    case KernelModel::PreIntegrated:
      return detail::preIntegratedComponents(truth);
    case KernelModel::Guided:
      return detail::guidedComponents(truth, s.guidedK, s.guidedB);
    case KernelModel::Manual:
      return detail::manualComponents(truth, s.manual);
    case KernelModel::Deon: {
      auto fit = fitGaussians(truth.profile, s.rank);
      if (!fit) return fit.error();
      return detail::gaussianComponents(truth, *fit);
    }
    case KernelModel::Jimenez:
      return detail::jimenezComponents(truth, s.jimenez);
  }
  return Error{"unknown kernel model"};
}

}  // namespace

Result<SeparableKernel> buildKernel(const GroundTruthKernel& truth, KernelModel model,
                                    const KernelSettings& s) {
  if (auto ok = checkSettings(model, s, truth.size()); !ok) return ok.error();
  auto dense = denseComponents(truth, model, s);
  if (!dense) return dense.error();
  SeparableKernel kernel;
  kernel.model = model;
  kernel.cellMm = truth.cellMm;
  kernel.halfCells = truth.halfCells;
  for (auto& d : *dense) {
    KernelComponent comp;
    // Jimenez's kernel has its own tap placement (the reference's quadratic offsets).
    comp.taps = model == KernelModel::Jimenez ? jimenezTaps(s.jimenez, s.taps)
                                              : detail::sampleTaps(d, truth.cellMm, s.taps);
    comp.sign = {static_cast<float>(d.sign[0]), static_cast<float>(d.sign[1]), static_cast<float>(d.sign[2])};
    comp.dense = std::move(d.a);
    kernel.components.push_back(std::move(comp));
  }
  return kernel;
}

Result<SeparableKernel> buildKernel(const RadialProfileRgb& profile, KernelModel model,
                                    const KernelSettings& s) {
  auto truth = groundTruthKernel(profile, s.gridHalfCells);
  if (!truth) return truth.error();
  return buildKernel(*truth, model, s);
}

Result<SeparableKernel> buildKernel(const ScatteringMaterial& material, KernelModel model,
                                    const KernelSettings& s) {
  auto profile = groundTruthProfile(material);
  if (!profile) return profile.error();
  KernelSettings settings = s;
  if (model == KernelModel::Manual && !(settings.manual.sigmaNearMm[0] > 0.0)) {
    auto table = manualParameters(material.name);
    if (!table) return table.error();
    settings.manual = *table;
  }
  return buildKernel(*profile, model, settings);
}

std::string_view kernelModelName(KernelModel model) {
  switch (model) {
    case KernelModel::Svd:
      return "svd";
    case KernelModel::PreIntegrated:
      return "preintegrated";
    case KernelModel::Guided:
      return "guided";
    case KernelModel::Manual:
      return "manual";
    case KernelModel::Deon:
      return "deon";
    case KernelModel::Jimenez:
      return "jimenez";
  }
  return "?";
}

Result<KernelModel> parseKernelModel(std::string_view name) {
  std::string lower(name);
  for (char& c : lower)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (KernelModel m : kModels)
    if (kernelModelName(m) == lower) return m;
  return Error{"kernel model '" + std::string(name) +
               "' is unknown; use svd, preintegrated, guided, manual, deon or jimenez"};
}

std::array<double, kChannels> kernelEnergy(const SeparableKernel& kernel) {
  std::array<double, kChannels> energy{};
  for (int c = 0; c < kChannels; ++c) {
    for (const auto& comp : kernel.components) {
      double s = 0;
      for (const auto& t : comp.taps)
        s += channelOf(t.weight, c);
      energy[static_cast<std::size_t>(c)] += channelOf(comp.sign, c) * s * s;
    }
  }
  return energy;
}

}  // namespace tissue::optics
