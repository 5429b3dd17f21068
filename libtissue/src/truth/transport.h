#pragma once
// Private: the light transport of the path-traced truth (path_tracer.h) for one camera path
// carrying all three bands at once. Spectral tracking (Kutz, Habel, Li & Novák 2017, "Spectral and
// decomposition tracking for rendering heterogeneous volumes", §5.2, with Wrenninge's history-aware
// collision probabilities) against one majorant over every band and layer: the event (real or
// null collision) is drawn once for the path from the weighted average of the bands' coefficients,
// and each band's weight takes the ratio of its own probability to the one drawn with. A real
// collision keeps the collision estimator's albedo weighting (sigma_s / sigma_t per band); the new
// direction comes from the one-sample MIS mixture of the bands' Henyey-Greenstein lobes (Veach
// 1997, §9.2.4; the "hero wavelength" of Wilkie et al. 2014 with the balance heuristic). The
// boundary (Fresnel, Snell) does not depend on the band. Next-event estimation shares its
// connection through the boundary between the bands and is itself Russian-rouletted where the
// collision is so deep that every band's transmittance bound is small.
//
// Local majorants (Yue et al. 2010, "Unbiased, adaptive stochastic sampling for rendering
// inhomogeneous participating media", piecewise-constant majorants along the ray; Novák et al.
// 2018, "Monte Carlo methods for volumetric light transport simulation", §3 and §6): the layer at
// a point depends on its depth only through each layer's depth range over the whole map, and the
// depth is 1-Lipschitz, so one nearest-surface query bounds the depth over a ball around it. A
// ray is tracked in segments, each inside such a ball, against the largest extinction of the
// layers the segment may meet; where those layers all have the same coefficients (the
// parenchyma above and below the liver's vessels) the segment needs no further query and its
// transmittance is exact. Free paths restart at each segment's end (memoryless): unbiased.
//
// The next collision's next event by multiple importance sampling (Veach 1997, §9.2, the balance
// heuristic with one sample per strategy). Next-event estimation evaluates the phase function
// between the path's direction and the light's refracted beam; with g = 0.9 that is up to ~190x
// its mean inside a cone of ~0.1 rad, so the rare paths that head up the beam near the surface
// carry most of a pixel's light, and the estimator's variance is dominated by them (heavy-tailed:
// the per-sample variance measured at 4, 32 spp grows 3 -> 14; with g = 0 at the same reduced
// scattering it is 1.4). At each real collision x whose next event found light l, the integral of
// l's next event at the *next* collision over the new direction is estimated by two strategies:
// the continuing path (direction from the phase function p) and one extra flight whose direction
// is drawn from a Henyey-Greenstein lobe q_l of the same g around the beam's reverse, -t_l. Each
// is weighted by its balance heuristic, p / (p + q_l) and q_l / (p + q_l); the product p q_l /
// (p + q_l) that reaches the pixel is at most min(p, q_l), so the peak is sampled where it lies.
// Only flights that reach the next collision without meeting the boundary take part (the extra
// flight scores nothing at the boundary; the path's next event after a boundary event keeps
// weight 1), and only where x's layer has one g for every band (the hero lobes then agree).

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "../optics/random_stream.h"
#include "tissue/subsurface/layer_stack.h"
#include "tissue/truth/path_tracer.h"

namespace tissue::truth::detail {

/// Per-thread tallies (integers: their sum does not depend on the split between threads).
struct PathStats {
  std::int64_t capped = 0;
  std::int64_t lost = 0;
  std::int64_t interactions = 0;
  std::int64_t nextEvents = 0;     ///< light connections traced
  std::int64_t skippedEvents = 0;  ///< light connections ended by their Russian roulette
  std::int64_t depthQueries = 0;   ///< nearest-surface queries (layer depths)
  std::int64_t guidedEvents = 0;   ///< extra flights of the next collision's next-event MIS
};

/// Per-thread, per-pixel scratch: the last connection normal per light (the next collision's
/// first guess of the fixed point in nextEvent). Reset at each pixel so that an image does not
/// depend on the rows a thread takes.
struct PathScratch {
  std::vector<glm::dvec3> lightNormal;
  std::vector<std::uint8_t> lightNormalValid;
  // The last next event's refracted beam direction per light (valid where it found the light),
  // and the balance-heuristic weight of each light's next event at the path's next collision
  // (1 where no lobe was armed; Transport::trace).
  std::vector<glm::dvec3> beam;
  std::vector<std::uint8_t> beamValid;
  std::vector<double> nextWeight;
  void reset(std::size_t lights) {
    lightNormal.assign(lights, glm::dvec3(0.0));
    lightNormalValid.assign(lights, 0);
    beam.assign(lights, glm::dvec3(0.0));
    beamValid.assign(lights, 0);
    nextWeight.assign(lights, 1.0);
  }
};

class Transport {
 public:
  Transport(const RayMesh& rays, const TruthMesh& mesh, const TruthMaterial& material,
            std::span<const TruthLight> lights, const PathTraceSettings& settings);

  /// Radiance (light units, per band) arriving along the ray o + t d (d unit) from the scene.
  /// `bands`: the initial band weights (all ones: the three bands on one path; a unit vector:
  /// that band alone, whose spectral tracking is then plain delta tracking).
  Rgb trace(glm::dvec3 o, glm::dvec3 d, optics::detail::RandomStream& rng, PathStats& stats,
            PathScratch& scratch, const Rgb& bands = {1.0, 1.0, 1.0}) const;

  std::size_t lightCount() const { return m_lights.size(); }

 private:
  // One layer, all bands.
  struct LayerBands {
    Rgb sigmaT{}, sigmaS{}, g{};  // mm^-1, mm^-1, mean cosine
    bool grey = true;             // g equal in every band
  };
  struct PreparedLight {
    bool directional = false;
    glm::dvec3 position{0.0};  // mm
    glm::dvec3 toLight{0.0};   // unit, directional lights
    Rgb irradiance{};          // pi * radiance: irradiance on a surface facing the light
    bool shadows = true;
  };
  // The path's last nearest-surface query (layerAt, depthBounds).
  struct DepthCache {
    glm::dvec3 x{0.0};     // where, mm
    double depthMm = 0.0;  // its depth, mm (a lower bound when not exact)
    bool exact = false;
    bool valid = false;
    std::int64_t* queries = nullptr;  // the path's tally of queries
  };
  // A piece of a ray from its start: its length, the majorant of every point on it, and the
  // layer whose coefficients hold all along it (-1: look the layer up at each collision).
  struct Segment {
    double lengthMm = 0.0;
    double majorant = 0.0;
    int layer = -1;
  };

  // How a flight inside the tissue ended (flyToCollision).
  enum class Flight { Collision, Boundary, Vanished, Capped };

  Flight flyToCollision(glm::dvec3& o, const glm::dvec3& d, double& toBoundary, Rgb& w, const Rgb& ratio,
                        optics::detail::RandomStream& rng, DepthCache& cache, int& events,
                        int& layerIndex) const;
  Rgb guidedNextEvent(const glm::dvec3& x, const glm::dvec3& dIn, double g, const glm::dvec3& lobe,
                      std::size_t light, const Rgb& w, optics::detail::RandomStream& rng, DepthCache& cache,
                      PathScratch& scratch, PathStats& stats) const;
  double hitDistance(const MeshHit& hit, const glm::dvec3& o, const glm::dvec3& d) const;
  void refreshDepth(const glm::dvec3& p, DepthCache& cache) const;
  int layerAt(const glm::dvec3& p, DepthCache& cache) const;
  int constantDepthLayer(double depthMm) const;
  void depthInterval(const glm::dvec3& p, const DepthCache& cache, double& lo, double& hi) const;
  std::uint64_t classesIn(double lo, double hi) const;
  Segment segmentFrom(double lo, double hi, double maxLengthMm) const;
  Segment segmentAt(const glm::dvec3& p, double maxLengthMm, DepthCache& cache) const;
  Rgb transmittance(const glm::dvec3& x, const glm::dvec3& dir, double length,
                    optics::detail::RandomStream& rng, DepthCache& cache) const;
  bool occluded(const glm::dvec3& from, const glm::dvec3& dir, double maxT) const;
  double neeSurvival(const glm::dvec3& y, const Rgb& w, DepthCache& cache) const;
  Rgb nextEvent(const glm::dvec3& y, const glm::dvec3& d, const LayerBands& layer, const Rgb& w,
                std::span<const double> lightWeights, int onlyLight, optics::detail::RandomStream& rng,
                DepthCache& cache, PathScratch& scratch, PathStats& stats) const;
  glm::dvec3 scatter(const glm::dvec3& d, const LayerBands& layer, std::size_t hero, Rgb& ratio,
                     optics::detail::RandomStream& rng) const;
  Rgb glossy(const glm::dvec3& p, const glm::dvec3& toEye, const glm::dvec3& n) const;
  glm::dvec3 shadingNormal(const MeshHit& hit) const;

  const RayMesh& m_rays;
  const TruthMesh& m_mesh;
  const PathTraceSettings& m_settings;
  double m_nTissue = 1.4, m_nAmbient = 1.0, m_eps = 1e-5;
  std::vector<glm::dvec3> m_faceNormal;
  // Per vertex: the corner-angle weighted normal over every triangle at its position (seams
  // welded), the smooth surface the renderer shades; the glossy reflection reads it.
  std::vector<glm::dvec3> m_vertexNormal;
  std::vector<glm::dvec3> m_faceVertex;  // each triangle's first vertex, mm
  std::vector<LayerBands> m_layers;
  // Local majorants: each layer's class (layers with equal coefficients share one), the depth
  // range it may occupy anywhere on the map (mm), each class's majorant and first layer.
  std::vector<int> m_layerClass;
  std::vector<double> m_layerTopMm, m_layerBottomMm;
  std::vector<double> m_classMajorant;
  std::vector<int> m_classLayer;
  bool m_localMajorants = false;
  double m_majorant = 0.0;     // mm^-1, the largest sigma_t over bands and layers
  Rgb m_sigmaTMin{};           // mm^-1, per band the smallest sigma_t over the layers
  double m_neeRadiusMm = 0.0;  // mm, how deep the depth queries look (the roulette's reach)
  int m_layerCount = 1;
  bool m_perTexel = false;
  subsurface::LayerStack m_stack;
  std::vector<double> m_boundaryMm;
  double m_deepestBoundaryMm = 0.0;  // mm, slightly beyond the deepest boundary
  std::vector<PreparedLight> m_lights;
};

}  // namespace tissue::truth::detail
