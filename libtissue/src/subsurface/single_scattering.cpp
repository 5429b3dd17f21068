// Ray-marched single scattering (François et al. 2006, Algorithms 1 and 2; Norberg 2010 §2.1, §3.1).
#include "tissue/subsurface/single_scattering.h"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "tissue/optics/schlick_phase.h"

namespace tissue::subsurface {
namespace {

using glm::dvec3;

constexpr double kSelfHitMm = 1e-3;  // mm: closer mesh hits are the surface the ray starts on

dvec3 d3(Float3 v) {
  return {v.x, v.y, v.z};
}

dvec3 normalizeOr(dvec3 v, dvec3 fallback) {
  const double len = glm::length(v);
  return len > 1e-12 ? v / len : fallback;
}

// The frame of one point, in double precision.
struct Frame {
  dvec3 P, wo, Np, Ns, PS, T, B;
  double uvPerMm = 0.0;
  Float2 uv;
  double tMax = 0.0;      // |PM_max|, mm
  double cosDepth = 0.0;  // depth gained per mm along the viewing ray (Algorithm 1: depthStep = PMstep . N)
};

Float2 uvAt(const Frame& f, const dvec3& X) {
  // Project PX into tangent space (François §2.1, Fig. 6): (ds, dt) = (PX . T, PX . B).
  const dvec3 PX = X - f.P;
  return {float(double(f.uv.x) + glm::dot(PX, f.T) * f.uvPerMm),
          float(double(f.uv.y) + glm::dot(PX, f.B) * f.uvPerMm)};
}

// Optical depth (per channel) of the light's path from K to M, given |KM| and the cosine of its
// angle to the layers: averaged layer thicknesses (Norberg eq. 13) and per-layer distances with
// the max(., 0) fix (Norberg eq. 14, §3.1.1).
dvec3 lightOpticalDepth(const LayerStack& stack, const Boundaries& atM, const Boundaries& atK, double KM,
                        double cosTheta) {
  dvec3 tau(0.0);
  double above = 0.0;  // sum_{j < i} D_j / cos(theta)
  const int layers = int(stack.layers.size());
  for (int i = 0; i < layers && above < KM; ++i) {
    const double D = i < atM.count ? 0.5 * double(layerThicknessMm(atM, i) + layerThicknessMm(atK, i)) : 1e30;
    const double di = std::min(std::max(KM - above, 0.0), D / cosTheta);
    tau += di * d3(stack.layers[i].sigma_t);
    above += D / cosTheta;
  }
  return tau;
}

// Reduced intensity factor exp(-tau_KM) for the light at `S` seen from sample M at distance t.
dvec3 reducedIntensity(const Frame& f, const LayerStack& stack, const Boundaries& atM, const dvec3& M,
                       double t, const dvec3& S, const TriangleBvh* mesh) {
  const dvec3 wi = normalizeOr(S - M, f.Np);
  double KM = 0.0, cosTheta = 1.0;
  if (mesh == nullptr) {
    // Plane through M: the tangent plane at P blended towards the fitted plane (eq. 9), with
    // alpha = |M M_max|, beta = |M P|. Algorithm 2 writes the weights the other way round
    // (N_SP at i = 0); eq. 9 and Norberg's eq. 10 put the tangent plane at P, as here.
    const double w = f.tMax > 0.0 ? t / f.tMax : 0.0;
    const dvec3 NM = normalizeOr((1.0 - w) * f.Np + w * f.Ns, f.Np);
    const dvec3 PM = (1.0 - w) * f.P + w * f.PS;
    cosTheta = glm::dot(NM, wi);
    if (cosTheta <= 1e-4) return dvec3(0.0);         // the light is behind the plane: no entry point
    KM = std::abs(glm::dot(M - PM, NM)) / cosTheta;  // eq. 10
  } else {
    const auto hit = mesh->intersect({M.x, M.y, M.z}, {wi.x, wi.y, wi.z}, 0.0, 1e9);
    if (!hit) return dvec3(1.0);  // M is outside the mesh: the light arrives unattenuated
    KM = hit->t;
    const auto n = mesh->faceNormal(hit->triangle);
    cosTheta = std::max(std::abs(glm::dot(dvec3(n[0], n[1], n[2]), wi)), 1e-4);
  }
  const dvec3 K = M + KM * wi;
  const Boundaries atK = sampleBoundaries(stack, uvAt(f, K));
  return glm::exp(-lightOpticalDepth(stack, atM, atK, KM, cosTheta));
}

// Smallest extinction of any layer and channel, mm^-1 (the slowest attenuation).
double sigmaMin(const LayerStack& stack) {
  double sigma = 1e30;
  for (const LayerCoefficients& l : stack.layers)
    sigma = std::min({sigma, double(l.sigma_t.x), double(l.sigma_t.y), double(l.sigma_t.z)});
  return sigma;
}

Frame makeFrame(const ShadingPoint& p, const LayerStack& stack, const MarchSettings& s) {
  Frame f;
  f.P = d3(p.position);
  f.wo = normalizeOr(d3(p.toEye), dvec3(0, 0, 1));
  f.Np = normalizeOr(d3(p.normal), f.wo);
  f.Ns = normalizeOr(dvec3(p.plane.x, p.plane.y, p.plane.z), f.Np);
  f.PS = f.P + double(p.plane.w) * f.Np;  // a point of the fitted plane (eq. 14)
  f.T = d3(p.tangent);
  f.B = d3(p.bitangent);
  f.uv = p.uv;
  f.uvPerMm = p.uvPerMm;
  // M_max along the fitted-plane normal (eq. 15), clamped at grazing views; no further than
  // where the viewing path alone has attenuated light below the threshold (the march would
  // stop there anyway, so the samples go where light still returns).
  const double cosView = std::max(glm::dot(f.Ns, f.wo), double(s.minCosView));
  f.tMax = double(s.depthMaxMm) / cosView;
  if (s.attenuationThreshold > 0.0f)
    f.tMax = std::min(f.tMax, -std::log(double(s.attenuationThreshold)) / sigmaMin(stack));
  f.tMax = std::min(f.tMax, double(s.maxLengthMm));
  f.cosDepth = std::max(glm::dot(f.Np, f.wo), 0.0);
  return f;
}

}  // namespace

MarchResult marchSingleScattering(const ShadingPoint& point, const LayerStack& stack,
                                  std::span<const Light> lights, const MarchSettings& settings, float jitter,
                                  const TriangleBvh* mesh) {
  Frame f = makeFrame(point, stack, settings);
  if (mesh != nullptr) {
    // Mesh mode: the viewing ray ends where it leaves the tissue. P arrives in float (about
    // 1e-5 mm off the surface at 100 mm), so hits closer than kSelfHitMm are P's own triangle.
    const dvec3 in = -f.wo;
    if (const auto exit = mesh->intersect({f.P.x, f.P.y, f.P.z}, {in.x, in.y, in.z}, kSelfHitMm, f.tMax))
      f.tMax = exit->t;
  }
  MarchResult result;
  const int n = std::max(settings.samples, 1);
  const double dt = f.tMax / n;
  dvec3 L(0.0), attenuation(1.0);  // attenuation = exp(-tau_PM), eq. 13
  for (int i = 0; i < n; ++i) {
    // Step heading: locate M, its texel and its layer (Algorithm 1, FindLayer).
    const double t = (i + double(jitter)) * dt;
    const dvec3 M = f.P - t * f.wo;
    const Boundaries atM = sampleBoundaries(stack, uvAt(f, M));
    const int layer = findLayer(atM, float(t * f.cosDepth));
    const LayerCoefficients& c = stack.layers[std::min<std::size_t>(layer, stack.layers.size() - 1)];
    attenuation *= glm::exp(-d3(c.sigma_t) * (i == 0 ? double(jitter) * dt : dt));
    // Scatter the reduced light of every source towards the eye (eq. 2).
    const double k = optics::schlickKFromG(c.g);
    for (const Light& light : lights) {
      const dvec3 S = d3(light.positionMm);
      const dvec3 wi = normalizeOr(S - M, f.Np);
      const double phase = optics::schlickPhase(-glm::dot(wi, f.wo), k);  // cos t between travel directions
      const dvec3 Lri = d3(light.radiance) * reducedIntensity(f, stack, atM, M, t, S, mesh);
      L += d3(c.sigma_s) * phase * Lri * attenuation * dt;  // eq. 5
    }
    result.samplesUsed = i + 1;
    if (settings.attenuationThreshold > 0.0f &&
        std::max({attenuation.x, attenuation.y, attenuation.z}) < double(settings.attenuationThreshold))
      break;
  }
  result.radiance = {float(L.x), float(L.y), float(L.z)};
  return result;
}

float pixelJitter(unsigned x, unsigned y, unsigned seed) {
  // PCG hash (Jarzynski and Olano 2020), chained over the three inputs.
  auto pcg = [](std::uint32_t v) {
    const std::uint32_t state = v * 747796405u + 2891336453u;
    const std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
  };
  return float(pcg(x + pcg(y + pcg(seed))) >> 8) * (1.0f / 16777216.0f);
}

AdaptiveChoice adaptiveMarch(const ShadingPoint& point, const LayerStack& stack, const MarchSettings& march,
                             const AdaptiveSettings& adaptive, float pixelMm) {
  const Frame f = makeFrame(point, stack, march);
  // Length: where the round trip has attenuated light below the cutoff.
  const double roundTrip = -std::log(double(adaptive.cutoff)) / (sigmaMin(stack) * (1.0 + f.cosDepth));
  const double length = std::min(f.tMax, roundTrip);
  // Count: the depth it covers, and how far it drifts sideways in texture space.
  const double depthMm = length * f.cosDepth;
  const double lateralMm = length * std::sqrt(std::max(1.0 - f.cosDepth * f.cosDepth, 0.0));
  const double texelMm = stack.maps.width > 0 ? 1.0 / (f.uvPerMm * stack.maps.width) : 1e30;
  const double stepMm = double(adaptive.texelsPerStep) * std::max(texelMm, double(pixelMm));
  const double want = std::max(depthMm / double(adaptive.depthResolutionMm), lateralMm / stepMm);
  return {std::clamp(int(std::ceil(want)), adaptive.minSamples, adaptive.maxSamples), float(length)};
}

}  // namespace tissue::subsurface
