// One batch of MCML photons (Wang, Jacques & Zheng 1995, MCML manual chapter 3): hop, drop, spin,
// cross or reflect, roulette. Step names follow the MCML manual.
#include "photon_batch.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "random_stream.h"
#include "tissue/optics/fresnel.h"
#include "tissue/optics/phase_function.h"

namespace tissue::optics::detail {
namespace {

constexpr double kWeightThreshold = 1e-4;  // MCML's roulette threshold
constexpr double kSurvivalChance = 0.1;    // MCML's roulette survival chance
constexpr double kCosZero = 1.0 - 1e-12;   // |uz| above this: the direction is along z
constexpr double kInf = std::numeric_limits<double>::infinity();

struct Photon {
  double x = 0, y = 0, z = 0;     // mm
  double ux = 0, uy = 0, uz = 1;  // direction cosines
  double w = 1;                   // weight
  double sleft = 0;               // dimensionless step left after a boundary
  int layer = 0;
  bool alive = true;
};

// New direction after scattering by cos t and the azimuth (cos phi, sin phi) (MCML manual, "Spin").
void spin(Photon& p, double cosT, double cosP, double sinP) {
  const double sinT = std::sqrt(std::max(0.0, 1.0 - cosT * cosT));
  if (std::abs(p.uz) > kCosZero) {
    p.ux = sinT * cosP;
    p.uy = sinT * sinP;
    p.uz = p.uz > 0.0 ? cosT : -cosT;  // cosT keeps its sign (backward scattering)
    return;
  }
  const double temp = std::sqrt(1.0 - p.uz * p.uz);
  const double ux = sinT * (p.ux * p.uz * cosP - p.uy * sinP) / temp + p.ux * cosT;
  const double uy = sinT * (p.uy * p.uz * cosP + p.ux * sinP) / temp + p.uy * cosT;
  p.uz = -sinT * cosP * temp + p.uz * cosT;
  p.ux = ux;
  p.uy = uy;
}

class BatchRunner {
 public:
  BatchRunner(const LayeredMedium& medium, const RadialGrid& grid, std::uint64_t seed, std::uint64_t stream)
      : m_medium(medium), m_grid(grid), m_rng(seed, stream) {
    double z = 0;
    for (const auto& layer : medium.layers) {
      m_top.push_back(z);
      z += layer.thickness;
      m_bottom.push_back(z);
    }
    m_tally.absorbed.assign(medium.layers.size(), 0.0);
    m_tally.rdRing.assign(static_cast<std::size_t>(grid.bins), 0.0);
    m_tally.ttRing.assign(static_cast<std::size_t>(grid.bins), 0.0);
  }

  void run(Photon p, std::int64_t maxInteractions) {
    for (std::int64_t hops = 0; p.alive; ++hops) {
      if (hops == maxInteractions) {
        ++m_tally.capped;
        m_tally.cappedWeight += p.w;
        return;
      }
      step(p);
      if (p.alive && p.w < kWeightThreshold) roulette(p);
    }
  }
  BatchTally&& take() { return std::move(m_tally); }

 private:
  // One hop: to the next interaction site, or to the layer boundary if that is nearer.
  void step(Photon& p) {
    const Layer& layer = m_medium.layers[static_cast<std::size_t>(p.layer)];
    const double mut = layer.mua + layer.mus;
    if (p.sleft == 0.0) p.sleft = -std::log(m_rng.uniform());
    double toBoundary = kInf;
    if (p.uz > 0.0) toBoundary = (m_bottom[static_cast<std::size_t>(p.layer)] - p.z) / p.uz;
    if (p.uz < 0.0) toBoundary = (m_top[static_cast<std::size_t>(p.layer)] - p.z) / p.uz;
    const double s = mut > 0.0 ? p.sleft / mut : kInf;
    if (s >= toBoundary) {
      p.x += toBoundary * p.ux;
      p.y += toBoundary * p.uy;
      p.z =
          p.uz > 0.0 ? m_bottom[static_cast<std::size_t>(p.layer)] : m_top[static_cast<std::size_t>(p.layer)];
      if (mut > 0.0) p.sleft = std::max(0.0, p.sleft - toBoundary * mut);
      crossOrReflect(p);
      return;
    }
    p.x += s * p.ux;
    p.y += s * p.uy;
    p.z += s * p.uz;
    p.sleft = 0.0;
    // Drop: deposit the absorbed part of the weight.
    const double dw = p.w * layer.mua / mut;
    p.w -= dw;
    m_tally.absorbed[static_cast<std::size_t>(p.layer)] += dw;
    // Spin: Henyey-Greenstein polar angle, uniform azimuth.
    const double cosT = sampleHenyeyGreenstein(layer.g, m_rng.uniform());
    double cosP = 0.0, sinP = 0.0;
    m_rng.azimuth(cosP, sinP);
    spin(p, cosT, cosP, sinP);
  }

  // Fresnel reflection or transmission at the boundary the photon sits on.
  void crossOrReflect(Photon& p) {
    const bool down = p.uz > 0.0;
    const int next = down ? p.layer + 1 : p.layer - 1;
    const int layers = static_cast<int>(m_medium.layers.size());
    const bool leaves = next < 0 || next >= layers;
    const double n1 = m_medium.layers[static_cast<std::size_t>(p.layer)].n;
    const double n2 = next < 0 ? m_medium.ambientAbove
                               : (next >= layers ? m_medium.ambientBelow
                                                 : m_medium.layers[static_cast<std::size_t>(next)].n);
    const FresnelResult fr = fresnelReflectance(n1, n2, std::abs(p.uz));
    if (fr.reflectance > 0.0 && m_rng.uniform() <= fr.reflectance) {
      p.uz = -p.uz;
      return;
    }
    if (leaves) {
      score(p, down);
      p.alive = false;
      return;
    }
    p.layer = next;
    p.ux *= n1 / n2;
    p.uy *= n1 / n2;
    p.uz = std::copysign(fr.cosTransmitted, p.uz);
  }

  // Radial and total scoring of an escaping photon.
  void score(const Photon& p, bool transmitted) {
    (transmitted ? m_tally.tt : m_tally.rd) += p.w;
    const double ring = std::floor(std::sqrt(p.x * p.x + p.y * p.y) / m_grid.drMm);
    if (ring < m_grid.bins)
      (transmitted ? m_tally.ttRing : m_tally.rdRing)[static_cast<std::size_t>(ring)] += p.w;
  }

  // Russian roulette: survive with chance 0.1 carrying weight W / 0.1.
  void roulette(Photon& p) {
    if (m_rng.uniform() <= kSurvivalChance)
      p.w /= kSurvivalChance;
    else
      p.alive = false;
  }

  const LayeredMedium& m_medium;
  const RadialGrid& m_grid;
  RandomStream m_rng;
  std::vector<double> m_top, m_bottom;  // z of each layer's faces, mm
  BatchTally m_tally;
};

}  // namespace

BatchTally runPhotonBatch(const LayeredMedium& medium, const RadialGrid& grid, std::int64_t photons,
                          std::int64_t maxInteractions, std::uint64_t seed, std::uint64_t stream,
                          std::atomic<std::int64_t>& progress) {
  BatchRunner runner(medium, grid, seed, stream);
  const double launchWeight = 1.0 - specularReflectance(medium);
  constexpr std::int64_t kProgressChunk = 1024;
  for (std::int64_t i = 0; i < photons; ++i) {
    Photon p;
    p.w = launchWeight;
    runner.run(p, maxInteractions);
    if ((i + 1) % kProgressChunk == 0) progress.fetch_add(kProgressChunk, std::memory_order_relaxed);
  }
  progress.fetch_add(photons % kProgressChunk, std::memory_order_relaxed);
  return runner.take();
}

}  // namespace tissue::optics::detail
