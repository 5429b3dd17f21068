// The path-traced truth (path_tracer.h): camera paths through a Fresnel boundary into a layered
// medium, delta tracking, next-event estimation of the lights through the boundary.
#include "tissue/truth/path_tracer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <string>
#include <system_error>
#include <thread>

#include <glm/glm.hpp>

#include "../optics/random_stream.h"  // the Monte Carlo codes share one generator (header only)
#include "interface_math.h"
#include "tissue/core/vec_math.h"
#include "tissue/optics/fresnel.h"
#include "tissue/optics/phase_function.h"

namespace tissue::truth {
namespace {

using V = glm::dvec3;
using optics::detail::RandomStream;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = std::numbers::pi;
constexpr double kSurvivalChance = 0.1;  // MCML's roulette survival chance

std::array<double, 3> arr(const V& v) {
  return {v.x, v.y, v.z};
}
V v3(Float3 f) {
  return {f.x, f.y, f.z};
}
double sq(double x) {
  return x * x;
}

// One layer in one band.
struct LayerBand {
  double sigmaT = 0.0;  // mm^-1
  double sigmaS = 0.0;  // mm^-1
  double g = 0.0;
};

struct PreparedLight {
  bool directional = false;
  V position{0.0};   // mm
  V toLight{0.0};    // unit, directional lights
  Rgb irradiance{};  // pi * radiance: irradiance on a surface facing the light
  bool shadows = true;
};

// The path's last nearest-surface query (Transport::layerAt).
struct DepthCache {
  V x{0.0};              // where, mm
  double depthMm = 0.0;  // its depth, mm (a lower bound when not exact)
  bool exact = false;
  bool valid = false;
};
constexpr double kDepthBallMm = 1.0;  // mm searched beyond the deepest boundary

// Per-thread tallies (integers: their sum does not depend on the split between threads).
struct PathStats {
  std::int64_t capped = 0;
  std::int64_t lost = 0;
  std::int64_t interactions = 0;
};

// Everything the paths read, prepared once per render.
class Transport {
 public:
  Transport(const RayMesh& rays, const TruthMesh& mesh, const TruthMaterial& material,
            std::span<const TruthLight> lights, const PathTraceSettings& settings)
      : m_rays(rays), m_mesh(mesh), m_settings(settings) {
    m_nTissue = material.layers.front().n;
    m_nAmbient = material.ambientN;
    double maxAbs = 1.0;
    for (const Float3& p : mesh.positions)
      maxAbs = std::max({maxAbs, std::abs(double(p.x)), std::abs(double(p.y)), std::abs(double(p.z))});
    // Ray offsets off the surface: several single-precision ulps of the coordinates (Embree).
    m_eps = std::max(1e-5, 2e-6 * maxAbs);
    for (const Triangle& t : mesh.triangles) {
      const V a = v3(mesh.positions[t[0]]), b = v3(mesh.positions[t[1]]), c = v3(mesh.positions[t[2]]);
      const V n = glm::cross(b - a, c - a);
      const double len = glm::length(n);
      m_faceNormal.push_back(len > 0.0 ? n / len : V(0.0));
      m_faceVertex.push_back(a);
    }
    for (int band = 0; band < kBands; ++band) {
      const auto b = static_cast<std::size_t>(band);
      double majorant = 0.0;
      for (const TruthLayer& layer : material.layers) {
        const LayerBand lb{(*layer.sigmaA)[b] + (*layer.sigmaS)[b], (*layer.sigmaS)[b], layer.g[b]};
        majorant = std::max(majorant, lb.sigmaT);
        m_layers[b].push_back(lb);
      }
      m_majorant[b] = majorant;
    }
    m_layerCount = int(material.layers.size());
    m_perTexel = material.maps.mapCount > 0;
    if (m_perTexel) {
      m_stack.maps = material.maps;
      m_stack.depthScaleMm = material.depthScaleMm;
      float deepest = 0.0f;
      for (float v : material.maps.depths)
        deepest = std::max(deepest, v);
      m_deepestBoundaryMm = 1.001 * double(deepest) * double(material.depthScaleMm) + 1e-9;
    } else {
      double depth = 0.0;
      for (std::size_t i = 0; i + 1 < material.layers.size(); ++i)
        m_boundaryMm.push_back(depth += material.layers[i].thicknessMm);
      m_deepestBoundaryMm = 1.001 * depth + 1e-9;
    }
    for (const TruthLight& l : lights) {
      PreparedLight p;
      p.directional = l.type == TruthLightType::Directional;
      p.position = v3(l.positionMm);
      p.toLight = -glm::normalize(v3(l.direction));
      p.irradiance = {kPi * double(l.radiance.x), kPi * double(l.radiance.y), kPi * double(l.radiance.z)};
      p.shadows = l.castsShadows;
      m_lights.push_back(p);
    }
  }

  // Radiance (light units) arriving along the ray o + t d from the scene, in `band`.
  double trace(int band, V o, V d, RandomStream& rng, PathStats& stats) const {
    const auto b = static_cast<std::size_t>(band);
    const double majorant = m_majorant[b];
    const bool single = m_settings.estimator == Estimator::SingleScattering;
    double radiance = 0.0, weight = 1.0;
    bool inside = false;
    DepthCache cache;
    for (int events = 0;; ++events) {
      if (events >= m_settings.maxInteractions) {
        ++stats.capped;
        break;
      }
      const auto hit = m_rays.intersect(arr(o), arr(d), 0.0, kInf);
      if (!inside) {
        if (!hit) break;  // no environment: light comes from the lights only
        const V p = o + hitDistance(*hit, o, d) * d;
        const V n = m_faceNormal[hit->triangle];
        const double cosI = -glm::dot(d, n);
        if (cosI <= 0.0) {  // a back face seen from outside: the mesh is not closed
          ++stats.lost;
          break;
        }
        if (m_settings.surfaceRoughness > 0.0) radiance += weight * glossy(band, p, -d, n);
        const optics::FresnelResult fr = optics::fresnelReflectance(m_nAmbient, m_nTissue, cosI);
        if (rng.uniform() <= fr.reflectance) {  // choose reflection with probability R
          d = detail::reflect(d, n);
          o = p + m_eps * n;
          continue;
        }
        d = detail::refract(d, n, m_nAmbient / m_nTissue, cosI, fr.cosTransmitted);
        o = p - m_eps * n;
        weight *= sq(m_nAmbient / m_nTissue);  // radiance leaving the tissue: T (n_out / n_in)^2
        inside = true;
        continue;
      }
      if (!hit) {  // a ray from inside that meets nothing: the mesh is not closed
        ++stats.lost;
        break;
      }
      // Delta tracking against the band's majorant (Woodcock et al. 1965).
      const double flight = majorant > 0.0 ? -std::log(rng.uniform()) / majorant : kInf;
      const double toBoundary = hitDistance(*hit, o, d);
      if (flight < toBoundary) {
        const V y = o + flight * d;
        const LayerBand& layer = m_layers[b][static_cast<std::size_t>(layerAt(y, cache))];
        o = y;
        if (layer.sigmaT < majorant && rng.uniform() * majorant >= layer.sigmaT) continue;  // null collision
        ++stats.interactions;
        weight *= layer.sigmaS / layer.sigmaT;  // the collision estimator's albedo weight
        radiance += weight * nextEvent(band, y, d, layer.g, rng, cache);
        if (single) break;
        d = detail::scatterDirection(d, optics::sampleHenyeyGreenstein(layer.g, rng.uniform()),
                                     rng.uniform());
        if (weight < m_settings.rouletteWeight) {
          if (rng.uniform() > kSurvivalChance) break;
          weight /= kSurvivalChance;
        }
        continue;
      }
      // The boundary, from inside: Fresnel reflection (total internal reflection) or exit.
      const V q = o + toBoundary * d;
      const V n = m_faceNormal[hit->triangle];
      const double cosI = glm::dot(d, n);
      if (cosI <= 0.0) {
        ++stats.lost;
        break;
      }
      const optics::FresnelResult fr = optics::fresnelReflectance(m_nTissue, m_nAmbient, cosI);
      if (rng.uniform() <= fr.reflectance) {
        d = detail::reflect(d, n);
        o = q - m_eps * n;
        continue;
      }
      d = detail::refract(d, -n, m_nTissue / m_nAmbient, cosI, fr.cosTransmitted);
      o = q + m_eps * n;
      weight *= sq(m_nTissue / m_nAmbient);
      inside = false;
    }
    return radiance;
  }

 private:
  // The hit's distance recomputed in double precision on the triangle's plane: Embree's single
  // precision t is off by ~1e-7 of the ray's length, more than the surface offsets for far eyes.
  double hitDistance(const MeshHit& hit, const V& o, const V& d) const {
    const V& n = m_faceNormal[hit.triangle];
    const double dn = glm::dot(d, n);
    return std::abs(dn) > 1e-9 ? glm::dot(m_faceVertex[hit.triangle] - o, n) / dn : hit.t;
  }

  // The layer at interior point p: by its depth, the distance to the nearest surface point. The
  // depth is 1-Lipschitz, so a query at x bounds it within |p - x| of x's depth: `cache` keeps the
  // path's last query and skips those whose layer the bound already decides (exact, no bias).
  int layerAt(const V& p, DepthCache& cache) const {
    if (m_layerCount == 1) return 0;
    if (cache.valid) {
      const double s = glm::length(p - cache.x);
      if (cache.depthMm - s > m_deepestBoundaryMm) return m_layerCount - 1;
      if (cache.exact && !m_perTexel) {
        const int lo = constantDepthLayer(std::max(0.0, cache.depthMm - s));
        if (lo == constantDepthLayer(cache.depthMm + s)) return lo;
      }
    }
    // Search a little beyond the deepest boundary, so that deep points get a ball to reuse.
    const double radius = m_deepestBoundaryMm + kDepthBallMm;
    const std::optional<SurfacePoint> found = m_rays.nearest(arr(p), radius);
    cache = {p, found ? found->distanceMm : radius, found.has_value(), true};
    if (!found || found->distanceMm > m_deepestBoundaryMm) return m_layerCount - 1;
    const SurfacePoint& np = *found;
    if (!m_perTexel) return constantDepthLayer(np.distanceMm);
    const Triangle& t = m_mesh.triangles[np.triangle];
    const double w0 = 1.0 - np.b1 - np.b2;
    const Float2 a = m_mesh.uvs[t[0]], b = m_mesh.uvs[t[1]], c = m_mesh.uvs[t[2]];
    const Float2 uv{float(w0 * double(a.x) + np.b1 * double(b.x) + np.b2 * double(c.x)),
                    float(w0 * double(a.y) + np.b1 * double(b.y) + np.b2 * double(c.y))};
    return subsurface::findLayer(subsurface::sampleBoundaries(m_stack, uv), float(np.distanceMm));
  }

  int constantDepthLayer(double depthMm) const {
    int layer = 0;
    while (layer < int(m_boundaryMm.size()) && m_boundaryMm[std::size_t(layer)] <= depthMm)
      ++layer;
    return layer;
  }

  // Transmittance along x + t dir, t in [0, length]: exact in one layer, ratio tracking
  // (Cramer 1978; Novák et al. 2014) against the majorant in several.
  double transmittance(int band, const V& x, const V& dir, double length, RandomStream& rng,
                       DepthCache& cache) const {
    const auto b = static_cast<std::size_t>(band);
    if (m_layerCount == 1) return std::exp(-m_layers[b][0].sigmaT * length);
    const double majorant = m_majorant[b];
    if (majorant <= 0.0) return 1.0;
    double t = 0.0, tr = 1.0;
    while (true) {
      t -= std::log(rng.uniform()) / majorant;
      if (t >= length) return tr;
      tr *= 1.0 - m_layers[b][static_cast<std::size_t>(layerAt(x + t * dir, cache))].sigmaT / majorant;
      if (tr <= 0.0) return 0.0;
    }
  }

  bool occluded(const V& from, const V& dir, double maxT) const {
    return m_rays.intersect(arr(from), arr(dir), 0.0, maxT).has_value();
  }

  // Next-event estimation at the real collision y of a path travelling along d: the light that
  // refracts into the tissue, travels unscattered to y and scatters into -d. The connection through
  // the boundary is found on the mesh by a fixed point: refract the light at a guessed face normal,
  // trace back from y, repeat with the face met until it is the same (exact on flat faces).
  double nextEvent(int band, const V& y, const V& d, double g, RandomStream& rng, DepthCache& cache) const {
    const auto b = static_cast<std::size_t>(band);
    const double eta = m_nAmbient / m_nTissue;
    double sum = 0.0;
    for (const PreparedLight& light : m_lights) {
      if (light.irradiance[b] <= 0.0) continue;
      V toLight = light.directional ? light.toLight : glm::normalize(light.position - y);
      V n = toLight;  // first guess: normal incidence
      bool found = false;
      V travel(0.0), q(0.0);
      double cosI = 0.0, cosT = 0.0, length = 0.0;
      // A point light's direction moves with the exit point: the error shrinks by about
      // |y - q| / |light - q| per iteration, so a lamp 20 mm away converges in a few.
      for (int iteration = 0; iteration < 12 && !found; ++iteration) {
        cosI = glm::dot(toLight, n);
        if (cosI <= 0.0) break;
        const optics::FresnelResult fr = optics::fresnelReflectance(m_nAmbient, m_nTissue, cosI);
        if (fr.reflectance >= 1.0) break;
        cosT = fr.cosTransmitted;
        travel = detail::refract(-toLight, n, eta, cosI, cosT);
        const auto hit = m_rays.intersect(arr(y), arr(-travel), 0.0, kInf);
        if (!hit) break;
        length = hitDistance(*hit, y, -travel);
        q = y - length * travel;
        const V nf = m_faceNormal[hit->triangle];
        const V toLightNew = light.directional ? toLight : glm::normalize(light.position - q);
        found = glm::dot(nf, n) > 1.0 - 1e-12 && glm::dot(toLightNew, toLight) > 1.0 - 1e-10;
        n = nf;
        toLight = toLightNew;
      }
      if (!found || glm::dot(-travel, n) <= 0.0) continue;
      const double transmitted = 1.0 - optics::fresnelReflectance(m_nAmbient, m_nTissue, cosI).reflectance;
      // Collimated irradiance inside: the flux T E cos(theta_i) per unit area over cos(theta_t).
      const double irradianceInside = transmitted * light.irradiance[b] * cosI / cosT;
      const double tr = transmittance(band, y, -travel, length, rng, cache);
      if (tr <= 0.0) continue;
      if (light.shadows &&
          occluded(q + m_eps * n, toLight, light.directional ? kInf : glm::length(light.position - q)))
        continue;
      sum += optics::henyeyGreenstein(glm::dot(travel, -d), g) * irradianceInside * tr;
    }
    return sum;
  }

  // The lights reflected by the outer surface at p towards `toEye`: a Beckmann microfacet lobe
  // (Walter et al. 2007: D eq. 25, Smith G1 rational form eq. 27, f_r eq. 20) with Fresnel at the
  // half vector.
  double glossy(int band, const V& p, const V& toEye, const V& n) const {
    const auto b = static_cast<std::size_t>(band);
    const double alpha = m_settings.surfaceRoughness;
    const double cosV = glm::dot(n, toEye);
    auto g1 = [&](double cosine) {
      const double tanTheta = std::sqrt(std::max(0.0, 1.0 - cosine * cosine)) / cosine;
      if (tanTheta <= 0.0) return 1.0;
      const double a = 1.0 / (alpha * tanTheta);
      return a < 1.6 ? (3.535 * a + 2.181 * a * a) / (1.0 + 2.276 * a + 2.577 * a * a) : 1.0;
    };
    double sum = 0.0;
    for (const PreparedLight& light : m_lights) {
      const V toLight = light.directional ? light.toLight : glm::normalize(light.position - p);
      const double cosL = glm::dot(n, toLight);
      if (cosL <= 0.0 || cosV <= 0.0) continue;
      const V h = glm::normalize(toLight + toEye);
      const double cosH = glm::dot(n, h);
      if (cosH <= 0.0) continue;
      const double tan2 = (1.0 - cosH * cosH) / (cosH * cosH);
      const double dist = std::exp(-tan2 / (alpha * alpha)) / (kPi * alpha * alpha * sq(sq(cosH)));
      const double fresnel =
          optics::fresnelReflectance(m_nAmbient, m_nTissue, glm::dot(toEye, h)).reflectance;
      const double fr = fresnel * dist * g1(cosV) * g1(cosL) / (4.0 * cosL * cosV);
      if (light.shadows &&
          occluded(p + m_eps * n, toLight, light.directional ? kInf : glm::length(light.position - p)))
        continue;
      sum += fr * light.irradiance[b] * cosL;
    }
    return sum;
  }

  const RayMesh& m_rays;
  const TruthMesh& m_mesh;
  const PathTraceSettings& m_settings;
  double m_nTissue = 1.4, m_nAmbient = 1.0, m_eps = 1e-5;
  std::vector<V> m_faceNormal;
  std::vector<V> m_faceVertex;  // each triangle's first vertex, mm
  std::array<std::vector<LayerBand>, kBands> m_layers;
  std::array<double, kBands> m_majorant{};
  int m_layerCount = 1;
  bool m_perTexel = false;
  subsurface::LayerStack m_stack;
  std::vector<double> m_boundaryMm;
  double m_deepestBoundaryMm = 0.0;  // mm, slightly beyond the deepest boundary: the search radius
  std::vector<PreparedLight> m_lights;
};

Result<void> validateInputs(const TruthMesh& mesh, const TruthMaterial& material,
                            std::span<const TruthLight> lights, const TruthCamera& camera,
                            const PathTraceSettings& s) {
  if (auto ok = validateMaterial(material); !ok) return ok;
  if (mesh.positions.empty() || mesh.triangles.empty())
    return Error{"path tracer: the mesh is empty; give a closed triangle mesh (positions in mm, triangles)"};
  if (!mesh.uvs.empty() && mesh.uvs.size() != mesh.positions.size())
    return Error{"path tracer: " + std::to_string(mesh.uvs.size()) + " UVs for " +
                 std::to_string(mesh.positions.size()) + " vertices; give one per vertex or none"};
  if (material.maps.mapCount > 0 && mesh.uvs.empty())
    return Error{"path tracer: per-texel layering (subsurface maps) needs the mesh's UVs"};
  if (s.width < 1 || s.height < 1) return Error{"path tracer: the image needs width and height >= 1 pixel"};
  if (s.samplesPerPass < 1 || s.passes < 1 || std::int64_t(s.samplesPerPass) * s.passes < 2)
    return Error{
        "path tracer: samplesPerPass and passes must be >= 1, with at least 2 samples per pixel in all "
        "(the standard error needs two)"};
  if (s.threads < 0) return Error{"path tracer: threads must be >= 0 (0: all cores)"};
  if (s.maxInteractions < 1) return Error{"path tracer: maxInteractions must be >= 1"};
  if (!std::isfinite(s.surfaceRoughness) || s.surfaceRoughness < 0.0 || s.surfaceRoughness > 1.0)
    return Error{"path tracer: surfaceRoughness must lie in [0, 1] (Beckmann alpha; 0: smooth)"};
  if (!(s.rouletteWeight >= 0.0 && s.rouletteWeight < 1.0))
    return Error{"path tracer: rouletteWeight must lie in [0, 1)"};
  for (std::size_t i = 0; i < lights.size(); ++i) {
    const TruthLight& l = lights[i];
    const std::string name = "path tracer: light " + std::to_string(i);
    if (!isFinite(l.radiance) || l.radiance.x < 0.0f || l.radiance.y < 0.0f || l.radiance.z < 0.0f)
      return Error{name + ": radiance must be finite and >= 0"};
    if (l.type == TruthLightType::Directional && (!isFinite(l.direction) || length(l.direction) <= 0.0f))
      return Error{name + ": a directional light needs a finite, non-zero direction"};
    if (l.type == TruthLightType::Point && !isFinite(l.positionMm))
      return Error{name + ": a point light needs a finite position (mm)"};
  }
  if (!isFinite(camera.eye) || !isFinite(camera.target) || !isFinite(camera.up) || length(camera.up) <= 0.0f)
    return Error{"path tracer: the camera needs finite eye, target and a non-zero up"};
  if (camera.projection == Projection::Pinhole &&
      (length(camera.target - camera.eye) <= 0.0f ||
       !(camera.verticalFovDeg > 0.0f && camera.verticalFovDeg < 180.0f)))
    return Error{
        "path tracer: the pinhole camera needs target != eye and a field of view in (0, 180) degrees"};
  if (camera.projection == Projection::CosineProbe && !(camera.probeDistanceMm > 0.0f))
    return Error{"path tracer: the cosine probe needs probeDistanceMm > 0"};
  return {};
}

// The camera ray of one sample: origin and unit direction.
struct CameraRay {
  V origin, dir;
};

class CameraRays {
 public:
  CameraRays(const TruthCamera& c, int width, int height) : m_camera(c), m_width(width), m_height(height) {
    m_normal = glm::normalize(v3(c.up));
  }
  CameraRay sample(int x, int y, RandomStream& rng, bool jitter) const {
    if (m_camera.projection == Projection::CosineProbe) {
      // Cosine-weighted direction around the normal (Malley's method).
      const double r = std::sqrt(rng.uniform()), phi = 2.0 * kPi * rng.uniform();
      const V w =
          detail::scatterDirection(m_normal, std::sqrt(std::max(0.0, 1.0 - r * r)), phi / (2.0 * kPi));
      return {v3(m_camera.target) + double(m_camera.probeDistanceMm) * w, -w};
    }
    const double jx = jitter ? rng.uniform() : 0.5, jy = jitter ? rng.uniform() : 0.5;
    const Float3 d = pinholeRayDirection(m_camera, m_width, m_height, x + jx, y + jy);
    return {v3(m_camera.eye), v3(d)};
  }
  CameraRay centre(int x, int y) const {
    if (m_camera.projection == Projection::CosineProbe)
      return {v3(m_camera.target) + double(m_camera.probeDistanceMm) * m_normal, -m_normal};
    return {v3(m_camera.eye), v3(pinholeRayDirection(m_camera, m_width, m_height, x + 0.5, y + 0.5))};
  }

 private:
  const TruthCamera& m_camera;
  int m_width, m_height;
  V m_normal;
};

// Sums per pixel and band over the samples so far.
struct Accumulator {
  std::vector<double> sum, sumSq;  // #pixels * 3
};

void finishImage(const Accumulator& acc, int samples, TruthImage& image) {
  const double n = samples;
  for (std::size_t i = 0; i < image.radiance.size(); ++i) {
    float mean[3], se[3];
    for (int c = 0; c < 3; ++c) {
      const double s = acc.sum[3 * i + std::size_t(c)], s2 = acc.sumSq[3 * i + std::size_t(c)];
      const double m = s / n;
      const double variance = std::max(0.0, (s2 - s * m) / (n - 1.0));
      mean[c] = float(m);
      se[c] = float(std::sqrt(variance / n));
    }
    image.radiance[i] = {mean[0], mean[1], mean[2]};
    image.stderrs[i] = {se[0], se[1], se[2]};
  }
  image.samplesPerPixel = samples;
}

double meanRelativeStderr(const TruthImage& image) {
  double sum = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < image.radiance.size(); ++i) {
    const V m = v3(image.radiance[i]), e = v3(image.stderrs[i]);
    const double lum = 0.2126 * m.x + 0.7152 * m.y + 0.0722 * m.z;
    if (!image.covered[i] || lum <= 0.0) continue;
    sum += std::sqrt(sq(0.2126 * e.x) + sq(0.7152 * e.y) + sq(0.0722 * e.z)) / lum;
    ++count;
  }
  return count ? sum / count : 0.0;
}

}  // namespace

Float3 pinholeRayDirection(const TruthCamera& camera, int width, int height, double px, double py) {
  // The basis of glm::lookAt and glm::perspective, as the renderer's and the CPU reference's.
  const V eye = v3(camera.eye);
  const V forward = glm::normalize(v3(camera.target) - eye);
  const V right = glm::normalize(glm::cross(forward, v3(camera.up)));
  const V up = glm::cross(right, forward);
  const double tanHalf = std::tan(double(camera.verticalFovDeg) * kPi / 360.0);
  const double aspect = double(width) / double(height);
  const double sx = (2.0 * px / width - 1.0) * tanHalf * aspect;
  const double sy = (1.0 - 2.0 * py / height) * tanHalf;
  const V d = glm::normalize(forward + sx * right + sy * up);
  return {float(d.x), float(d.y), float(d.z)};
}

Result<TruthImage> renderPathTraced(const TruthMesh& mesh, const TruthMaterial& material,
                                    std::span<const TruthLight> lights, const TruthCamera& camera,
                                    const PathTraceSettings& settings) {
  if (auto ok = validateInputs(mesh, material, lights, camera, settings); !ok) return ok.error();
  auto rays = makeRayMesh(mesh.positions, mesh.triangles, settings.intersector);
  if (!rays) return rays.error();
  const auto start = std::chrono::steady_clock::now();
  const Transport transport(**rays, mesh, material, lights, settings);
  const CameraRays cameraRays(camera, settings.width, settings.height);

  TruthImage image;
  image.width = settings.width;
  image.height = settings.height;
  image.intersector = (*rays)->kind();
  const std::size_t pixels = std::size_t(settings.width) * std::size_t(settings.height);
  image.radiance.assign(pixels, Float3{});
  image.stderrs.assign(pixels, Float3{});
  image.covered.assign(pixels, 0);
  for (int y = 0; y < settings.height; ++y)
    for (int x = 0; x < settings.width; ++x) {
      const CameraRay r = cameraRays.centre(x, y);
      image.covered[std::size_t(y) * settings.width + x] =
          (*rays)->intersect(arr(r.origin), arr(r.dir), 0.0, kInf) ? 1 : 0;
    }
  int threads = settings.threads > 0 ? settings.threads : int(std::thread::hardware_concurrency());
  threads = std::clamp(threads, 1, settings.height);
  image.threads = threads;

  Accumulator acc;
  acc.sum.assign(3 * pixels, 0.0);
  acc.sumSq.assign(3 * pixels, 0.0);
  std::vector<PathStats> stats(static_cast<std::size_t>(threads));
  for (int pass = 0; pass < settings.passes; ++pass) {
    std::atomic<int> nextRow{0};
    auto worker = [&](int w) {
      PathStats st;  // local: the threads' tallies would share a cache line
      for (int y = nextRow.fetch_add(1); y < settings.height; y = nextRow.fetch_add(1))
        for (int x = 0; x < settings.width; ++x) {
          const std::size_t pixel = std::size_t(y) * settings.width + x;
          // One stream per pixel and pass: the image does not depend on the thread count.
          RandomStream rng(settings.seed, std::uint64_t(pass) * pixels + pixel);
          for (int s = 0; s < settings.samplesPerPass; ++s) {
            const CameraRay r = cameraRays.sample(x, y, rng, settings.jitter);
            for (int band = 0; band < kBands; ++band) {
              const double value = transport.trace(band, r.origin, r.dir, rng, st);
              acc.sum[3 * pixel + std::size_t(band)] += value;
              acc.sumSq[3 * pixel + std::size_t(band)] += value * value;
            }
          }
        }
      PathStats& total = stats[std::size_t(w)];
      total.capped += st.capped;
      total.lost += st.lost;
      total.interactions += st.interactions;
    };
    std::vector<std::thread> pool;
    try {
      for (int t = 0; t < threads; ++t)
        pool.emplace_back(worker, t);
    } catch (const std::system_error& e) {
      nextRow.store(settings.height);
      for (auto& th : pool)
        th.join();
      return Error{std::string("path tracer: could not start a worker thread: ") + e.what() +
                   "; try threads = 1"};
    }
    for (auto& th : pool)
      th.join();
    image.passes = pass + 1;
    finishImage(acc, (pass + 1) * settings.samplesPerPass, image);
    image.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (settings.onPass) {
      PathTraceProgress progress{.passesDone = pass + 1,
                                 .passesTotal = settings.passes,
                                 .samplesPerPixel = image.samplesPerPixel,
                                 .seconds = image.seconds,
                                 .meanRelativeStderr = meanRelativeStderr(image),
                                 .image = &image};
      if (!settings.onPass(progress)) break;
    }
  }
  for (const PathStats& st : stats) {
    image.cappedPaths += st.capped;
    image.lostPaths += st.lost;
    image.interactions += st.interactions;
  }
  image.paths = std::int64_t(pixels) * image.samplesPerPixel * kBands;
  image.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return image;
}

}  // namespace tissue::truth
