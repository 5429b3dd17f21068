#include "tissue/materials/method_materials.h"

#include <cmath>
#include <numbers>

#include "tissue/optics/ground_truth_kernel.h"
#include "tissue/optics/kernel.h"
#include "tissue/optics/kernel_gaussians.h"

namespace tissue::materials {
namespace {

// The profile's values per channel as floats, normalised to integrate to 1.
reference::RadialProfile toReference(const optics::RadialProfileRgb& p) {
  reference::RadialProfile out;
  for (std::size_t i = 0; i < p.radiusMm.size(); ++i) {
    out.radiusMm.push_back(static_cast<float>(p.radiusMm[i]));
    out.value.push_back({static_cast<float>(p.value[0][i]), static_cast<float>(p.value[1][i]),
                         static_cast<float>(p.value[2][i])});
  }
  return reference::normalizedProfile(out);
}

// T(d) for a normalised profile R: the light crossing a slab of thickness d reaches the far
// side spread as R(sqrt(r^2 + d^2)) (Jimenez et al. 2010, eq. 3's construction).
std::vector<Float4> transmittanceTable(const reference::RadialProfile& R) {
  const float rMax = R.radiusMm.back();
  auto eval = [&](float r) {
    if (r >= rMax) return Float3{};
    std::size_t k = 0;
    while (k + 2 < R.radiusMm.size() && R.radiusMm[k + 1] < r)
      ++k;
    const float t = (r - R.radiusMm[k]) / (R.radiusMm[k + 1] - R.radiusMm[k]);
    const Float3 a = R.value[k], b = R.value[k + 1];
    return Float3{a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t};
  };
  std::vector<Float4> rows;
  constexpr int kRows = render::kMaxTransmittanceRows, kSteps = 400;
  for (int i = 0; i < kRows; ++i) {
    const float d = rMax * static_cast<float>(i) / (kRows - 1);
    Float3 sum{};
    const float dr = rMax / kSteps;
    for (int s = 0; s < kSteps; ++s) {
      const float r = (static_cast<float>(s) + 0.5f) * dr;
      const Float3 v = eval(std::sqrt(r * r + d * d));
      const float ring = 2.0f * std::numbers::pi_v<float> * r * dr;
      sum = {sum.x + v.x * ring, sum.y + v.y * ring, sum.z + v.z * ring};
    }
    rows.push_back({std::min(sum.x, 1.0f), std::min(sum.y, 1.0f), std::min(sum.z, 1.0f), d});
  }
  return rows;
}

}  // namespace

Result<SeparableMaterial> makeSeparableMaterial(const optics::ScatteringMaterial& material,
                                                const std::string& model, int taps, int rank) {
  auto kind = optics::parseKernelModel(model);
  if (!kind) return kind.error();
  if (rank != 1 && *kind != optics::KernelModel::Svd && *kind != optics::KernelModel::Deon) {
    return Error{"kernel '" + model + "' has rank 1; --rank " + std::to_string(rank) +
                 " applies to svd (SVD rank) and deon (Gaussian count) only"};
  }
  auto profile = optics::groundTruthProfile(material);
  if (!profile) return profile.error();
  optics::KernelSettings settings;
  settings.taps = taps;
  settings.rank = rank;  // SVD rank or d'Eon Gaussians: one pair of blur passes each
  // The surface's level is the optics' albedo and the blur only moves light: the rank-R SVD's
  // truncation loses 7-8 % of the profile's energy on the liver, so scale it back to a gain of
  // one (Freude eq. 5.12; docs/DECISIONS.md, "Every separable kernel keeps the energy"). The
  // other models are normalised as they are built.
  settings.normalizeEnergy = true;
  if (*kind == optics::KernelModel::Manual) {
    auto manual = optics::manualParameters(material.name);
    if (!manual) {
      return Error{"kernel 'manual' needs Freude's Table A.1 parameters, which material '" + material.name +
                   "' lacks: " + manual.error().message};
    }
    settings.manual = *manual;
  }
  auto kernel = optics::buildKernel(*profile, *kind, settings);
  if (!kernel) return Error{"kernel '" + model + "': " + kernel.error().message};
  SeparableMaterial out;
  for (const optics::KernelComponent& c : kernel->components) {
    render::SeparableComponent& component = out.settings.components.emplace_back();
    component.sign = c.sign;
    for (const optics::KernelTap& t : c.taps)
      component.taps.push_back({t.weight.x, t.weight.y, t.weight.z, t.offsetMm});
  }
  out.truth = toReference(*profile);
  out.settings.transmittance = transmittanceTable(out.truth);
  out.kernelName = std::string(optics::kernelModelName(*kind)) + (rank > 1 ? std::to_string(rank) : "") +
                   "-" + std::to_string(taps);
  return out;
}

Result<render::TextureSpaceSettings> makeTextureSpaceSettings(const optics::ScatteringMaterial& material,
                                                              int gaussians) {
  auto profile = optics::groundTruthProfile(material);
  if (!profile) return profile.error();
  auto sum = optics::fitGaussians(*profile, gaussians);
  if (!sum) return Error{"texture-space profile of '" + material.name + "': " + sum.error().message};
  render::TextureSpaceSettings out;
  for (std::size_t i = 0; i < sum->varianceMm2.size(); ++i) {
    out.gaussians.push_back({static_cast<float>(sum->varianceMm2[i]),
                             {static_cast<float>(sum->weights[0][i]), static_cast<float>(sum->weights[1][i]),
                              static_cast<float>(sum->weights[2][i])}});
  }
  out.transmittance = transmittanceTable(toReference(*profile));
  return out;
}

}  // namespace tissue::materials
