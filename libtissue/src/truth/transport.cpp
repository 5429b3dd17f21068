// The light transport of one camera path (transport.h): the boundary, spectral tracking, the
// collision estimator with next-event estimation, and the surface's glossy reflection.
#include "transport.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

#include "interface_math.h"
#include "tissue/optics/fresnel.h"
#include "tissue/optics/phase_function.h"

namespace tissue::truth::detail {
namespace {

using V = glm::dvec3;
using optics::detail::RandomStream;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = std::numbers::pi;
constexpr double kDepthBallMm = 1.0;  // mm searched beyond the deepest boundary
// Next-event estimation is Russian-rouletted where the bound max_b w_b exp(-sigma_t,min,b depth)
// on its weight falls below this; a surviving connection then carries at most this weight.
constexpr double kNeeRouletteWeight = 0.02;
constexpr double kNeeReachOptical = 7.0;  // optical depths the depth queries look (e^-7 ~ 1e-3)
constexpr double kMaxQueryRadiusMm = 50.0;
// Local majorants: a segment that may meet layers of several classes is this long at most (then
// re-examined), and the depth bounds of an earlier query are kept for a new segment when they
// give it at least one mean free flight against its majorant (else a fresh query).
constexpr double kMixedSegmentMm = 0.1;
constexpr double kMinSegmentMm = 1e-3;
// Layer depth ranges are widened by this much against the float arithmetic of the map lookups.
constexpr double kRangeSlackMm = 1e-5;

double maxOf(const Rgb& w) {
  return std::max({w[0], w[1], w[2]});
}
bool allZero(const Rgb& w) {
  return w[0] <= 0.0 && w[1] <= 0.0 && w[2] <= 0.0;
}
// The band weights times the balance heuristic of the hero directions (Transport::scatter):
// 3 ratio_b / sum(ratio), each band's direction density over the mean of the bands'.
Rgb withDirections(const Rgb& w, const Rgb& ratio) {
  const double k = 3.0 / (ratio[0] + ratio[1] + ratio[2]);
  return {w[0] * ratio[0] * k, w[1] * ratio[1] * k, w[2] * ratio[2] * k};
}

}  // namespace

Transport::Transport(const RayMesh& rays, const TruthMesh& mesh, const TruthMaterial& material,
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
  {
    // Weld by position, so a UV seam's copies share one normal as the mesh module's do.
    std::map<std::array<float, 3>, std::size_t> weld;
    std::vector<std::size_t> welded(mesh.positions.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      const Float3 p = mesh.positions[v];
      welded[v] = weld.try_emplace({p.x, p.y, p.z}, weld.size()).first->second;
    }
    std::vector<V> sum(weld.size(), V(0.0));
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
      const Triangle& t = mesh.triangles[f];
      for (int c = 0; c < 3; ++c) {
        const V p = v3(mesh.positions[t[c]]);
        const V e1 = v3(mesh.positions[t[(c + 1) % 3]]) - p, e2 = v3(mesh.positions[t[(c + 2) % 3]]) - p;
        const double l1 = glm::length(e1), l2 = glm::length(e2);
        if (l1 <= 0.0 || l2 <= 0.0) continue;
        const double angle = std::acos(std::clamp(glm::dot(e1, e2) / (l1 * l2), -1.0, 1.0));
        sum[welded[t[c]]] += angle * m_faceNormal[f];
      }
    }
    m_vertexNormal.resize(mesh.positions.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      const double len = glm::length(sum[welded[v]]);
      m_vertexNormal[v] = len > 0.0 ? sum[welded[v]] / len : V(0.0);
    }
  }
  m_sigmaTMin = {kInf, kInf, kInf};
  for (const TruthLayer& layer : material.layers) {
    LayerBands lb;
    for (std::size_t b = 0; b < std::size_t(kBands); ++b) {
      lb.sigmaS[b] = (*layer.sigmaS)[b];
      lb.sigmaT[b] = (*layer.sigmaA)[b] + (*layer.sigmaS)[b];
      lb.g[b] = layer.g[b];
      m_majorant = std::max(m_majorant, lb.sigmaT[b]);
      m_sigmaTMin[b] = std::min(m_sigmaTMin[b], lb.sigmaT[b]);
    }
    lb.grey = lb.g[0] == lb.g[1] && lb.g[1] == lb.g[2];
    m_layers.push_back(lb);
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
  const double weakest = std::min({m_sigmaTMin[0], m_sigmaTMin[1], m_sigmaTMin[2]});
  const double reach = weakest > 0.0 ? kNeeReachOptical / weakest : 0.0;
  m_neeRadiusMm = std::max(m_layerCount > 1 ? m_deepestBoundaryMm + kDepthBallMm : 0.0,
                           std::min(reach, kMaxQueryRadiusMm));
  // Local majorants: the classes of equal coefficients and each layer's depth range anywhere.
  for (std::size_t i = 0; i < m_layers.size(); ++i) {
    int cls = -1;
    for (std::size_t j = 0; j < i && cls < 0; ++j)
      if (m_layers[j].sigmaT == m_layers[i].sigmaT && m_layers[j].sigmaS == m_layers[i].sigmaS &&
          m_layers[j].g == m_layers[i].g)
        cls = m_layerClass[j];
    if (cls < 0) {
      cls = int(m_classMajorant.size());
      m_classMajorant.push_back(maxOf(m_layers[i].sigmaT));
      m_classLayer.push_back(int(i));
    }
    m_layerClass.push_back(cls);
  }
  m_localMajorants = settings.localMajorants && m_classMajorant.size() <= 64;
  const std::size_t boundaries = m_layers.size() - 1;
  std::vector<double> lowest(boundaries, kInf), highest(boundaries, 0.0);  // mm, per boundary
  if (m_perTexel) {
    // Bilinear lookups stay within the texels' range; the ordering clamp raises a boundary to at
    // most the largest of those above it.
    const std::size_t stride = std::size_t(material.maps.mapCount) * 4;
    for (std::size_t t = 0; t + stride <= material.maps.depths.size(); t += stride)
      for (std::size_t c = 0; c < boundaries; ++c) {
        const double v = double(material.maps.depths[t + c]) * double(material.depthScaleMm);
        lowest[c] = std::min(lowest[c], v);
        highest[c] = std::max(highest[c], v);
      }
    for (std::size_t c = 1; c < boundaries; ++c)
      highest[c] = std::max(highest[c], highest[c - 1]);
  } else {
    for (std::size_t c = 0; c < boundaries; ++c)
      lowest[c] = highest[c] = m_boundaryMm[c];
  }
  for (std::size_t i = 0; i < m_layers.size(); ++i) {
    m_layerTopMm.push_back(i == 0 ? 0.0 : lowest[i - 1] - kRangeSlackMm);
    m_layerBottomMm.push_back(i == boundaries ? kInf : highest[i] + kRangeSlackMm);
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

Rgb Transport::trace(V o, V d, RandomStream& rng, PathStats& stats, PathScratch& scratch,
                     const Rgb& bands) const {
  const bool single = m_settings.estimator == Estimator::SingleScattering;
  // w: the band weights of the boundary and the collisions; ratio: the bands' direction densities
  // over the hero band's (scatter); withDirections(w, ratio) is what a band carries.
  Rgb radiance{0.0, 0.0, 0.0}, w = bands, ratio{1.0, 1.0, 1.0};
  std::size_t hero = std::min<std::size_t>(2, std::size_t(3.0 * rng.uniform()));
  const bool oneBand = bands[0] + bands[1] + bands[2] == 1.0;
  if (oneBand) hero = bands[1] == 1.0 ? 1 : (bands[2] == 1.0 ? 2 : 0);  // its own lobe, no MIS
  bool inside = false, needRay = true;
  double toBoundary = 0.0;  // mm along d from o to the boundary (inside)
  std::uint32_t boundaryTriangle = 0;
  DepthCache cache;
  cache.queries = &stats.depthQueries;
  // MIS of the next collision's next events (transport.h): `armed` where the last real
  // collision set scratch.nextWeight for the next one, reached by one flight.
  const bool nextEventMis = m_settings.nextEventMis && !single && !m_lights.empty();
  bool armed = false;
  for (int events = 0;; ++events) {
    if (events >= m_settings.maxInteractions) {
      ++stats.capped;
      break;
    }
    // Outside: the camera ray or a reflected one meets the surface, or leaves.
    if (!inside) {
      const auto hit = m_rays.intersect(arr(o), arr(d), 0.0, kInf);
      if (!hit) break;  // no environment: light comes from the lights only
      const V p = o + hitDistance(*hit, o, d) * d;
      const V n = m_faceNormal[hit->triangle];
      const double cosI = -glm::dot(d, n);
      if (cosI <= 0.0) {  // a back face seen from outside: the mesh is not closed
        ++stats.lost;
        break;
      }
      if (m_settings.surfaceRoughness > 0.0) {
        // The highlight off the smooth surface the renderer draws (its interpolated normal); the
        // transport through the boundary keeps the flat triangle's.
        const Rgb gl = glossy(p, -d, shadingNormal(*hit)), carried = withDirections(w, ratio);
        for (std::size_t b = 0; b < 3; ++b)
          radiance[b] += carried[b] * gl[b];
      }
      const optics::FresnelResult fr = optics::fresnelReflectance(m_nAmbient, m_nTissue, cosI);
      if (rng.uniform() <= fr.reflectance) {  // choose reflection with probability R
        d = reflect(d, n);
        o = p + m_eps * n;
        continue;
      }
      d = refract(d, n, m_nAmbient / m_nTissue, cosI, fr.cosTransmitted);
      o = p - m_eps * n;
      const double k = sq(m_nAmbient / m_nTissue);  // radiance leaving the tissue: T (n_out / n_in)^2
      for (double& wb : w)
        wb *= k;
      inside = true;
      needRay = true;
      continue;
    }
    // Inside: the boundary ahead is found once per direction; null collisions keep it.
    if (needRay) {
      const auto hit = m_rays.intersect(arr(o), arr(d), 0.0, kInf);
      if (!hit) {  // a ray from inside that meets nothing: the mesh is not closed
        ++stats.lost;
        break;
      }
      toBoundary = hitDistance(*hit, o, d);
      boundaryTriangle = hit->triangle;
      needRay = false;
    }
    int layerIndex = -1;
    const Flight flight = flyToCollision(o, d, toBoundary, w, ratio, rng, cache, events, layerIndex);
    if (flight == Flight::Capped) {
      ++stats.capped;
      break;
    }
    if (flight == Flight::Vanished) break;
    if (flight == Flight::Collision) {
      ++stats.interactions;
      const LayerBands& layer = m_layers[static_cast<std::size_t>(layerIndex)];
      // This collision's next events, each light's weighted by the balance heuristic of the lobe
      // armed at the previous collision (1 where none was: after a boundary event, or none found).
      std::span<const double> weights;
      if (armed) weights = scratch.nextWeight;
      std::fill(scratch.beamValid.begin(), scratch.beamValid.end(), std::uint8_t(0));
      const Rgb nee =
          nextEvent(o, d, layer, withDirections(w, ratio), weights, -1, rng, cache, scratch, stats);
      for (std::size_t b = 0; b < 3; ++b)
        radiance[b] += nee[b];
      if (single || allZero(w)) break;
      const V dIn = d;
      d = scatter(d, layer, hero, ratio, rng);
      if (oneBand) ratio = {1.0, 1.0, 1.0};
      needRay = true;
      // The next collision's next events by MIS (transport.h): one extra flight per light whose
      // beam this collision found, and the weights the continuing path's next event will carry.
      armed = false;
      if (nextEventMis && layer.grey) {
        const double g = layer.g[0];
        const double pContinue = optics::henyeyGreenstein(glm::dot(dIn, d), g);
        const Rgb carried = withDirections(w, ratio);
        for (std::size_t li = 0; li < m_lights.size(); ++li) {
          scratch.nextWeight[li] = 1.0;
          if (!scratch.beamValid[li]) continue;
          const V lobe = -scratch.beam[li];
          const double qContinue = optics::henyeyGreenstein(glm::dot(lobe, d), g);
          scratch.nextWeight[li] = pContinue / (pContinue + qContinue);
          const Rgb extra = guidedNextEvent(o, dIn, g, lobe, li, carried, rng, cache, scratch, stats);
          for (std::size_t b = 0; b < 3; ++b)
            radiance[b] += extra[b];
          armed = true;
        }
      }
      // Russian roulette on the largest band's weight: survive with probability w / threshold.
      const double wMax = maxOf(withDirections(w, ratio));
      if (wMax < m_settings.rouletteWeight) {
        const double survive = wMax / m_settings.rouletteWeight;
        if (rng.uniform() > survive) break;
        for (double& wb : w)
          wb /= survive;
      }
      continue;
    }
    armed = false;  // the next collision is not reached by a flight from this one
    // The boundary, from inside: Fresnel reflection (total internal reflection) or exit.
    const V q = o + toBoundary * d;
    const V n = m_faceNormal[boundaryTriangle];
    const double cosI = glm::dot(d, n);
    if (cosI <= 0.0) {
      ++stats.lost;
      break;
    }
    needRay = true;
    const optics::FresnelResult fr = optics::fresnelReflectance(m_nTissue, m_nAmbient, cosI);
    if (rng.uniform() <= fr.reflectance) {
      d = reflect(d, n);
      o = q - m_eps * n;
      continue;
    }
    d = refract(d, -n, m_nTissue / m_nAmbient, cosI, fr.cosTransmitted);
    o = q + m_eps * n;
    const double k = sq(m_nTissue / m_nAmbient);
    for (double& wb : w)
      wb *= k;
    inside = false;
  }
  return radiance;
}

// Tracks from o along d (inside) to the first real collision before the boundary, toBoundary mm
// ahead: spectral tracking (Kutz et al. 2017, §5.2, history-aware: real with the probability of
// the weighted mean sigma_t, each band reweighted by its own over the one drawn with) against the
// local majorants, restarting at each segment's end (the exponential is memoryless). At a real
// collision o is there, w carries the collision estimator's albedo weighting and layerIndex is
// its layer; at the boundary o + toBoundary d is the boundary point. Each step counts an event.
Transport::Flight Transport::flyToCollision(V& o, const V& d, double& toBoundary, Rgb& w, const Rgb& ratio,
                                            RandomStream& rng, DepthCache& cache, int& events,
                                            int& layerIndex) const {
  Segment segment;
  double segmentLeft = 0.0;  // mm of the current segment ahead of o (0: make a new one)
  for (;; ++events) {
    if (events >= m_settings.maxInteractions) return Flight::Capped;
    if (segmentLeft <= 0.0) {
      segment = segmentAt(o, toBoundary, cache);
      segmentLeft = segment.lengthMm;
    }
    const double majorant = segment.majorant;
    const double flight = majorant > 0.0 ? -std::log(rng.uniform()) / majorant : kInf;
    if (flight >= segmentLeft && segmentLeft < toBoundary) {
      o += segmentLeft * d;
      toBoundary -= segmentLeft;
      segmentLeft = 0.0;
      continue;
    }
    if (flight >= toBoundary) return Flight::Boundary;
    o += flight * d;
    toBoundary -= flight;
    segmentLeft -= flight;
    layerIndex = segment.layer >= 0 ? segment.layer : layerAt(o, cache);
    const LayerBands& layer = m_layers[static_cast<std::size_t>(layerIndex)];
    const Rgb carried = withDirections(w, ratio);
    const double sumW = carried[0] + carried[1] + carried[2];
    if (!(sumW > 0.0)) return Flight::Vanished;
    const double pReal =
        (carried[0] * layer.sigmaT[0] + carried[1] * layer.sigmaT[1] + carried[2] * layer.sigmaT[2]) /
        (majorant * sumW);
    if (rng.uniform() > pReal) {  // null collision
      for (std::size_t b = 0; b < 3; ++b)
        w[b] *= (1.0 - layer.sigmaT[b] / majorant) / (1.0 - pReal);
      continue;
    }
    for (std::size_t b = 0; b < 3; ++b)
      w[b] *= layer.sigmaS[b] / (majorant * pReal);
    return Flight::Collision;
  }
}

// The second strategy of the next collision's next event for one light (transport.h): from the
// collision x that the path left along a direction drawn from HG(g) around dIn, a flight along a
// direction drawn from HG(g) around `lobe` (the light's beam reversed) to its first real
// collision, whose next event of that light carries p / q times the balance heuristic q / (p + q),
// i.e. p / (p + q). Nothing where it meets the boundary first (those paths belong to the
// continuing path alone).
Rgb Transport::guidedNextEvent(const V& x, const V& dIn, double g, const V& lobe, std::size_t light,
                               const Rgb& w, RandomStream& rng, DepthCache& cache, PathScratch& scratch,
                               PathStats& stats) const {
  const double cosTheta = optics::sampleHenyeyGreenstein(g, rng.uniform());
  double cosPhi = 0.0, sinPhi = 0.0;
  rng.azimuth(cosPhi, sinPhi);
  const V d = scatterDirection(lobe, cosTheta, cosPhi, sinPhi);
  ++stats.guidedEvents;
  const auto hit = m_rays.intersect(arr(x), arr(d), 0.0, kInf);
  if (!hit) return {0.0, 0.0, 0.0};
  V o = x;
  double toBoundary = hitDistance(*hit, x, d);
  Rgb weight = w;
  int events = 0, layerIndex = -1;
  if (flyToCollision(o, d, toBoundary, weight, {1.0, 1.0, 1.0}, rng, cache, events, layerIndex) !=
      Flight::Collision)
    return {0.0, 0.0, 0.0};
  const double p = optics::henyeyGreenstein(glm::dot(dIn, d), g);
  const double q = optics::henyeyGreenstein(glm::dot(lobe, d), g);
  const Rgb nee = nextEvent(o, d, m_layers[static_cast<std::size_t>(layerIndex)], weight, {}, int(light), rng,
                            cache, scratch, stats);
  const double mis = p / (p + q);
  return {nee[0] * mis, nee[1] * mis, nee[2] * mis};
}

// The hit's distance recomputed in double precision on the triangle's plane: Embree's single
// precision t is off by ~1e-7 of the ray's length, more than the surface offsets for far eyes.
double Transport::hitDistance(const MeshHit& hit, const V& o, const V& d) const {
  const V& n = m_faceNormal[hit.triangle];
  const double dn = glm::dot(d, n);
  return std::abs(dn) > 1e-9 ? glm::dot(m_faceVertex[hit.triangle] - o, n) / dn : hit.t;
}

// The depth of p (the distance to the nearest surface point) into `cache`, searched within the
// query radius (a lower bound of the radius when nothing is nearer).
void Transport::refreshDepth(const V& p, DepthCache& cache) const {
  const double radius = std::max(m_neeRadiusMm, 1e-6);
  const std::optional<SurfacePoint> found = m_rays.nearest(arr(p), radius);
  if (cache.queries) ++*cache.queries;
  cache.x = p;
  cache.depthMm = found ? found->distanceMm : radius;
  cache.exact = found.has_value();
  cache.valid = true;
}

// The depth range [lo, hi] of p from the cache's query (1-Lipschitz); none: [0, inf).
void Transport::depthInterval(const V& p, const DepthCache& cache, double& lo, double& hi) const {
  lo = 0.0;
  hi = kInf;
  if (!cache.valid) return;
  const double s = glm::length(p - cache.x);
  lo = std::max(0.0, cache.depthMm - s);
  if (cache.exact) hi = cache.depthMm + s;
}

// The classes of the layers whose depth range meets [lo, hi], as a bit mask.
std::uint64_t Transport::classesIn(double lo, double hi) const {
  std::uint64_t mask = 0;
  for (std::size_t i = 0; i < m_layers.size(); ++i)
    if (m_layerTopMm[i] <= hi && m_layerBottomMm[i] >= lo) mask |= std::uint64_t(1) << m_layerClass[i];
  return mask;
}

// The segment from a point whose depth lies in [lo, hi]: as long as the depths it can reach,
// [lo - L, hi + L], meet no layer of another class (at most maxLengthMm; kMixedSegmentMm where
// several classes are possible already).
Transport::Segment Transport::segmentFrom(double lo, double hi, double maxLengthMm) const {
  std::uint64_t mask = classesIn(lo, hi);
  double length = maxLengthMm;
  for (std::size_t j = 0; j < m_layers.size(); ++j) {
    if (mask & (std::uint64_t(1) << m_layerClass[j])) continue;
    length = std::min(length, m_layerBottomMm[j] < lo ? lo - m_layerBottomMm[j] : m_layerTopMm[j] - hi);
  }
  if (std::popcount(mask) > 1) length = std::min(length, kMixedSegmentMm);
  if (length < std::min(kMinSegmentMm, maxLengthMm)) {
    length = std::min(kMinSegmentMm, maxLengthMm);
    mask = classesIn(std::max(0.0, lo - length), hi + length);
  }
  Segment segment{length, 0.0, -1};
  for (std::size_t c = 0; c < m_classMajorant.size(); ++c)
    if (mask & (std::uint64_t(1) << c)) segment.majorant = std::max(segment.majorant, m_classMajorant[c]);
  if (std::popcount(mask) == 1) segment.layer = m_classLayer[std::size_t(std::countr_zero(mask))];
  return segment;
}

// The segment of the ray from p (at most maxLengthMm): from the cache's depth bounds where they
// give a one-class segment of at least a mean free flight, else from a fresh query at p.
Transport::Segment Transport::segmentAt(const V& p, double maxLengthMm, DepthCache& cache) const {
  if (!m_localMajorants) return {maxLengthMm, m_majorant, m_layerCount == 1 ? 0 : -1};
  if (m_classMajorant.size() == 1) return {maxLengthMm, m_classMajorant[0], 0};
  double lo = 0.0, hi = kInf;
  if (cache.valid) {
    depthInterval(p, cache, lo, hi);
    const Segment s = segmentFrom(lo, hi, maxLengthMm);
    if (s.layer >= 0 && s.lengthMm * s.majorant >= std::min(1.0, maxLengthMm * s.majorant)) return s;
  }
  refreshDepth(p, cache);
  depthInterval(p, cache, lo, hi);
  return segmentFrom(lo, hi, maxLengthMm);
}

// The layer at interior point p: by its depth. The depth is 1-Lipschitz, so a query at x bounds
// it within |p - x| of x's depth: `cache` keeps the path's last query and skips those whose layer
// the bound already decides (exact, no bias).
int Transport::layerAt(const V& p, DepthCache& cache) const {
  if (m_layerCount == 1) return 0;
  if (cache.valid) {
    const double s = glm::length(p - cache.x);
    if (cache.depthMm - s > m_deepestBoundaryMm) return m_layerCount - 1;
    if (m_localMajorants) {  // every layer the depth bounds allow has the same coefficients
      double lo = 0.0, hi = kInf;
      depthInterval(p, cache, lo, hi);
      const std::uint64_t mask = classesIn(lo, hi);
      if (std::popcount(mask) == 1) return m_classLayer[std::size_t(std::countr_zero(mask))];
    } else if (cache.exact && !m_perTexel) {
      const int lo = constantDepthLayer(std::max(0.0, cache.depthMm - s));
      if (lo == constantDepthLayer(cache.depthMm + s)) return lo;
    }
  }
  const std::optional<SurfacePoint> found = m_rays.nearest(arr(p), m_neeRadiusMm);
  if (cache.queries) ++*cache.queries;
  cache.x = p;
  cache.depthMm = found ? found->distanceMm : m_neeRadiusMm;
  cache.exact = found.has_value();
  cache.valid = true;
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

int Transport::constantDepthLayer(double depthMm) const {
  int layer = 0;
  while (layer < int(m_boundaryMm.size()) && m_boundaryMm[std::size_t(layer)] <= depthMm)
    ++layer;
  return layer;
}

// Transmittance per band along x + t dir, t in [0, length]: exact in one layer, ratio tracking
// (Cramer 1978; Novák et al. 2014) against the common majorant in several; with local majorants,
// exact along each one-class segment and ratio tracking against the segment's majorant elsewhere.
Rgb Transport::transmittance(const V& x, const V& dir, double length, RandomStream& rng,
                             DepthCache& cache) const {
  if (m_layerCount == 1) {
    const Rgb& s = m_layers[0].sigmaT;
    return {std::exp(-s[0] * length), std::exp(-s[1] * length), std::exp(-s[2] * length)};
  }
  Rgb tr{1.0, 1.0, 1.0};
  if (m_localMajorants) {
    double t = 0.0;
    while (length - t > 1e-12) {
      const V start = x + t * dir;
      const Segment seg = segmentAt(start, length - t, cache);
      if (seg.layer >= 0) {
        const Rgb& s = m_layers[std::size_t(seg.layer)].sigmaT;
        for (std::size_t b = 0; b < 3; ++b)
          tr[b] *= std::exp(-s[b] * seg.lengthMm);
      } else {
        for (double u = 0.0;;) {
          u -= std::log(rng.uniform()) / seg.majorant;
          if (u >= seg.lengthMm) break;
          const Rgb& s = m_layers[static_cast<std::size_t>(layerAt(start + u * dir, cache))].sigmaT;
          for (std::size_t b = 0; b < 3; ++b)
            tr[b] *= 1.0 - s[b] / seg.majorant;
          if (allZero(tr)) return tr;
        }
      }
      t += seg.lengthMm;
    }
    return tr;
  }
  if (m_majorant <= 0.0) return tr;
  double t = 0.0;
  while (true) {
    t -= std::log(rng.uniform()) / m_majorant;
    if (t >= length) return tr;
    const Rgb& s = m_layers[static_cast<std::size_t>(layerAt(x + t * dir, cache))].sigmaT;
    for (std::size_t b = 0; b < 3; ++b)
      tr[b] *= 1.0 - s[b] / m_majorant;
    if (allZero(tr)) return tr;
  }
}

bool Transport::occluded(const V& from, const V& dir, double maxT) const {
  return m_rays.intersect(arr(from), arr(dir), 0.0, maxT).has_value();
}

// The survival probability of next-event estimation at y. Any connection from y to the surface
// is at least depth(y) long, so band b's transmittance is at most exp(-sigma_t,min,b depth); where
// the bound B = max_b w_b exp(...) is below kNeeRouletteWeight the connection survives with
// probability B / kNeeRouletteWeight (Russian roulette: unbiased). The depth comes from the
// path's depth cache (1-Lipschitz bounds) and a fresh query only where the bounds cannot decide.
double Transport::neeSurvival(const V& y, const Rgb& w, DepthCache& cache) const {
  if (!(m_neeRadiusMm > 0.0)) return 1.0;
  auto bound = [&](double depthMm) {
    double b = 0.0;
    for (std::size_t i = 0; i < 3; ++i)
      b = std::max(b, w[i] * std::exp(-m_sigmaTMin[i] * depthMm));
    return b;
  };
  double lower = 0.0, upper = kInf;
  if (cache.valid) {
    const double s = glm::length(y - cache.x);
    lower = std::max(0.0, cache.depthMm - s);
    if (cache.exact) upper = cache.depthMm + s;
  }
  if (bound(lower) >= kNeeRouletteWeight) {
    // A query can only help if the point may lie deep enough for the bound to drop.
    if (bound(std::min(upper, m_neeRadiusMm)) >= kNeeRouletteWeight) return 1.0;
    refreshDepth(y, cache);
    lower = cache.depthMm;
  }
  const double b = bound(lower);
  return b >= kNeeRouletteWeight ? 1.0 : b / kNeeRouletteWeight;
}

// Next-event estimation at the real collision y of a path travelling along d, with the band
// weights w: the light that refracts into the tissue, travels unscattered to y and scatters into
// -d. The connection through the boundary is found on the mesh by a fixed point: refract the light
// at a guessed face normal, trace back from y, repeat with the face met until it is the same
// (exact on flat faces). The first guess is the face this light connected through at the path's
// previous collision (or normal incidence): nearby collisions connect through the same face, so
// one ray usually confirms it.
Rgb Transport::nextEvent(const V& y, const V& d, const LayerBands& layer, const Rgb& w,
                         std::span<const double> lightWeights, int onlyLight, RandomStream& rng,
                         DepthCache& cache, PathScratch& scratch, PathStats& stats) const {
  Rgb sum{0.0, 0.0, 0.0};
  const double survive = neeSurvival(y, w, cache);
  if (survive < 1.0 && rng.uniform() > survive) {
    ++stats.skippedEvents;
    return sum;
  }
  ++stats.nextEvents;
  const double eta = m_nAmbient / m_nTissue;
  for (std::size_t li = 0; li < m_lights.size(); ++li) {
    if (onlyLight >= 0 && li != std::size_t(onlyLight)) continue;
    const PreparedLight& light = m_lights[li];
    V toLight = light.directional ? light.toLight : glm::normalize(light.position - y);
    V n = scratch.lightNormalValid[li] ? scratch.lightNormal[li] : toLight;
    bool found = false;
    V travel(0.0), q(0.0);
    double cosI = 0.0, cosT = 0.0, length = 0.0;
    // A point light's direction moves with the exit point: the error shrinks by about
    // |y - q| / |light - q| per iteration, so a lamp 20 mm away converges in a few.
    for (int iteration = 0; iteration < 12 && !found; ++iteration) {
      cosI = glm::dot(toLight, n);
      if (cosI <= 0.0) {
        if (iteration > 0 || !scratch.lightNormalValid[li]) break;
        n = toLight;  // the cached face faces away from this light here: restart at normal incidence
        cosI = 1.0;
      }
      const optics::FresnelResult fr = optics::fresnelReflectance(m_nAmbient, m_nTissue, cosI);
      if (fr.reflectance >= 1.0) break;
      cosT = fr.cosTransmitted;
      travel = refract(-toLight, n, eta, cosI, cosT);
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
    scratch.lightNormal[li] = n;
    scratch.lightNormalValid[li] = 1;
    scratch.beam[li] = travel;
    scratch.beamValid[li] = 1;
    const double transmitted = 1.0 - optics::fresnelReflectance(m_nAmbient, m_nTissue, cosI).reflectance;
    const Rgb tr = transmittance(y, -travel, length, rng, cache);
    if (allZero(tr)) continue;
    if (light.shadows &&
        occluded(q + m_eps * n, toLight, light.directional ? kInf : glm::length(light.position - q)))
      continue;
    // Collimated irradiance inside: the flux T E cos(theta_i) per unit area over cos(theta_t).
    const double misWeight = lightWeights.empty() ? 1.0 : lightWeights[li];
    const double inside = transmitted * cosI / cosT / survive * misWeight;
    const double cosScatter = glm::dot(travel, -d);
    const double phase0 = optics::henyeyGreenstein(cosScatter, layer.g[0]);
    for (std::size_t b = 0; b < 3; ++b) {
      const double phase = layer.grey ? phase0 : optics::henyeyGreenstein(cosScatter, layer.g[b]);
      sum[b] += w[b] * phase * light.irradiance[b] * inside * tr[b];
    }
  }
  return sum;
}

// The new direction after a real collision: Henyey-Greenstein of the path's hero band (drawn
// once per path). Where the bands' g differ, `ratio` keeps each band's direction density of the
// path so far over the hero's; bandFactors turns it into the balance heuristic over the bands'
// whole-path strategies (Wilkie et al. 2014, "Hero wavelength spectral sampling"; Veach 1997,
// §9.2), which stays within 3x each band's own estimator however long the path.
V Transport::scatter(const V& d, const LayerBands& layer, std::size_t hero, Rgb& ratio,
                     RandomStream& rng) const {
  const double cosTheta = optics::sampleHenyeyGreenstein(layer.g[hero], rng.uniform());
  double cosPhi = 0.0, sinPhi = 0.0;
  rng.azimuth(cosPhi, sinPhi);
  if (!layer.grey) {
    const double heroPhase = optics::henyeyGreenstein(cosTheta, layer.g[hero]);
    for (std::size_t b = 0; b < 3; ++b)
      ratio[b] =
          std::clamp(ratio[b] * optics::henyeyGreenstein(cosTheta, layer.g[b]) / heroPhase, 1e-200, 1e200);
  }
  return scatterDirection(d, cosTheta, cosPhi, sinPhi);
}

V Transport::shadingNormal(const MeshHit& hit) const {
  const Triangle& t = m_mesh.triangles[hit.triangle];
  const V n = (1.0 - hit.b1 - hit.b2) * m_vertexNormal[t[0]] + hit.b1 * m_vertexNormal[t[1]] +
              hit.b2 * m_vertexNormal[t[2]];
  const double len = glm::length(n);
  return len > 0.0 ? n / len : m_faceNormal[hit.triangle];
}

// The lights reflected by the outer surface at p towards `toEye`: a Beckmann microfacet lobe
// (Walter et al. 2007: D eq. 25, Smith G1 rational form eq. 27, f_r eq. 20) with Fresnel at the
// half vector.
Rgb Transport::glossy(const V& p, const V& toEye, const V& n) const {
  const double alpha = m_settings.surfaceRoughness;
  const double cosV = glm::dot(n, toEye);
  auto g1 = [&](double cosine) {
    const double tanTheta = std::sqrt(std::max(0.0, 1.0 - cosine * cosine)) / cosine;
    if (tanTheta <= 0.0) return 1.0;
    const double a = 1.0 / (alpha * tanTheta);
    return a < 1.6 ? (3.535 * a + 2.181 * a * a) / (1.0 + 2.276 * a + 2.577 * a * a) : 1.0;
  };
  Rgb sum{0.0, 0.0, 0.0};
  for (const PreparedLight& light : m_lights) {
    const V toLight = light.directional ? light.toLight : glm::normalize(light.position - p);
    const double cosL = glm::dot(n, toLight);
    if (cosL <= 0.0 || cosV <= 0.0) continue;
    const V h = glm::normalize(toLight + toEye);
    const double cosH = glm::dot(n, h);
    if (cosH <= 0.0) continue;
    const double tan2 = (1.0 - cosH * cosH) / (cosH * cosH);
    const double dist = std::exp(-tan2 / (alpha * alpha)) / (kPi * alpha * alpha * sq(sq(cosH)));
    const double fresnel = optics::fresnelReflectance(m_nAmbient, m_nTissue, glm::dot(toEye, h)).reflectance;
    const double fr = fresnel * dist * g1(cosV) * g1(cosL) / (4.0 * cosL * cosV);
    if (light.shadows &&
        occluded(p + m_eps * n, toLight, light.directional ? kInf : glm::length(light.position - p)))
      continue;
    for (std::size_t b = 0; b < 3; ++b)
      sum[b] += fr * light.irradiance[b] * cosL;
  }
  return sum;
}

}  // namespace tissue::truth::detail
