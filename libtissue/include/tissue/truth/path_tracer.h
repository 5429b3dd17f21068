#pragma once
/// \file
/// The path-traced truth: volumetric random-walk Monte Carlo of light inside a closed triangle
/// mesh filled with a layered material (tissue/truth/material.h), seen by a pinhole camera and lit
/// by the renderer's lights (point and directional, without distance falloff). GL-free.
///
/// Per pixel sample, one camera path carries all three bands (Veach 1997, ch. 8; the random walk
/// of pbrt-v3 §15 and Cycles): it enters the surface with Fresnel reflection or refraction (Snell;
/// unpolarised Fresnel, tissue/optics/fresnel.h; total internal reflection inside), walks by
/// spectral tracking (Kutz et al. 2017: delta tracking, Woodcock et al. 1965, against one majorant
/// over the bands, each band's weight corrected by the ratio of its collision probability to the
/// one drawn with), weights each real collision by the albedo sigma_s / sigma_t per band, scatters
/// by Henyey-Greenstein (the lobe of a hero band drawn per path, with the balance heuristic over the bands'
/// whole-path densities where their g differ: Wilkie et al. 2014), and reflects or refracts again at every
/// boundary crossing. At every real collision it adds next-event estimation of every light through the
/// boundary: the refracted connection found on the mesh, the light's transmitted irradiance T E cos(theta_i)
/// / cos(theta_t) (flux conservation across the interface), the medium's transmittance (exact in one layer,
/// ratio tracking in several) and a shadow ray outside; deep collisions, whose every band's transmittance
/// bound is small, connect by Russian roulette. Radiance leaving the tissue carries T (n_out / n_in)^2 (Veach
/// 1997, §5.2). docs/DECISIONS.md ("The path-traced truth") lists what the estimator leaves out.
///
/// Deterministic for a seed: every pixel and pass has its own random stream, so an image does
/// not depend on the thread count. Progressive: passes of `samplesPerPass` samples per pixel are
/// accumulated; after each, `onPass` sees the running estimate and may stop the render. Each
/// pixel carries its standard error from the spread of its samples.

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/types.h"
#include "tissue/truth/material.h"
#include "tissue/truth/ray_mesh.h"

namespace tissue::truth {

/// A closed, consistently oriented triangle mesh (counter-clockwise seen from outside), mm.
struct TruthMesh {
  std::span<const Float3> positions;    ///< #V, mm
  std::span<const Triangle> triangles;  ///< #F
  std::span<const Float2> uvs;          ///< #V or empty; needed for per-texel layering
};

/// The renderer's two light types (tissue::render::LightType), mirrored so that this module
/// does not depend on the renderer.
enum class TruthLightType { Point, Directional };

/// One light without distance falloff, as the renderer's (render::Light): its `radiance` is the
/// renderer's colour * intensity, i.e. a white Lambertian surface facing the light returns that
/// radiance, so the irradiance on a surface facing it is pi * radiance. A point light shines from
/// its position along the direction to each point (far compared with a mean free path).
struct TruthLight {
  TruthLightType type = TruthLightType::Point;
  Float3 positionMm{150.0f, 200.0f, 250.0f};  ///< mm (point lights)
  Float3 direction{-0.4f, -0.6f, -0.7f};      ///< unitless, the way the light travels (directional)
  Float3 radiance{2.5f, 2.425f, 2.3f};        ///< linear RGB, the renderer's colour * intensity
  bool castsShadows = true;                   ///< trace a shadow ray from the surface towards the light
};

/// What the camera is.
enum class Projection {
  Pinhole,      ///< a perspective look-at camera (render::Camera without the clip planes)
  CosineProbe,  ///< every pixel measures the radiosity at `target`: cosine-weighted rays from
                ///< the hemisphere around `up` (the outward normal there) aimed at `target`
};

/// The camera. The pinhole's image rows run top to bottom; pixel centres as the renderer's.
struct TruthCamera {
  Projection projection = Projection::Pinhole;
  Float3 eye{0.0f, 0.0f, 200.0f};   ///< mm (pinhole)
  Float3 target{0.0f, 0.0f, 0.0f};  ///< mm, the point looked at (the probe's surface point)
  Float3 up{0.0f, 1.0f, 0.0f};      ///< unitless (the probe: the outward surface normal at target)
  float verticalFovDeg = 40.0f;     ///< degrees, full vertical field of view (pinhole)
  float probeDistanceMm = 1.0f;     ///< mm, where the probe's rays start above the target
};

/// What the paths estimate.
enum class Estimator {
  Full,              ///< all orders of scattering
  SingleScattering,  ///< only light scattered once (next-event estimation at the first collision)
};

/// One report after a pass (on the calling thread).
struct PathTraceProgress {
  int passesDone = 0;                        ///< passes accumulated so far
  int passesTotal = 0;                       ///< passes asked for
  int samplesPerPixel = 0;                   ///< samples accumulated per pixel so far
  double seconds = 0.0;                      ///< wall-clock time so far, s
  double meanRelativeStderr = 0.0;           ///< mean over covered pixels of stderr / radiance (luminance)
  const struct TruthImage* image = nullptr;  ///< the running estimate (valid during the call)
};

/// How to render.
struct PathTraceSettings {
  int width = 160;         ///< pixels
  int height = 120;        ///< pixels
  int samplesPerPass = 8;  ///< samples per pixel per pass (>= 1)
  int passes = 8;          ///< passes (>= 1); samples per pixel = passes * samplesPerPass
  std::uint64_t seed = 1;  ///< every random stream derives from it
  int threads = 0;         ///< worker threads; 0: std::thread::hardware_concurrency()
  Intersector intersector = Intersector::Best;
  Estimator estimator = Estimator::Full;
  int maxInteractions = 100000;  ///< per path (collisions, null collisions, boundary events); a path
                                 ///< that reaches it ends and is counted in TruthImage::cappedPaths
  /// Beckmann roughness alpha of the outer surface's reflection of the lights (Walter et al.
  /// 2007, eq. 25 and 27); 0: a smooth surface, whose mirror image of a point light covers no
  /// pixel. The renderer's Blinn-Phong exponent s corresponds to alpha = sqrt(2 / (s + 2)).
  /// Transport through the surface always treats it as smooth.
  double surfaceRoughness = 0.0;
  bool jitter = true;  ///< pinhole: sample uniformly within each pixel (else its centre)
  /// true: one path carries the three bands (spectral tracking); false: a path per band (the
  /// same transport with one band's weight, i.e. delta tracking of that band against the common
  /// majorant): slower, but no spread of the weights between bands.
  bool spectral = true;
  /// Russian roulette where the path's largest band weight w falls below this: it survives with
  /// probability w / rouletteWeight and then carries rouletteWeight.
  double rouletteWeight = 0.1;
  /// true: track against local majorants (Yue et al. 2010; transport.h), segments of the ray
  /// whose depth range can only meet some layers; false: one majorant over every layer and band
  /// (the same estimator, more null collisions and depth queries). Both are unbiased.
  bool localMajorants = true;
  /// true: the next collision's next event of each light is estimated by two strategies combined
  /// by the balance heuristic, the continuing path and an extra flight drawn towards the light's
  /// refracted beam (Veach 1997, §9.2; docs/DECISIONS.md, "The truth samples the beam's phase
  /// peak"): far lower variance where the phase function is forward-peaked; false: the path's own
  /// next events alone. Both are unbiased.
  bool nextEventMis = true;
  /// After each pass; return false to stop early (the image then holds the passes done). Empty:
  /// no reports. The library never writes to stderr itself.
  std::function<bool(const PathTraceProgress&)> onPass;
};

/// Linear radiance per pixel, rows top to bottom, in the lights' radiance units.
struct TruthImage {
  int width = 0;
  int height = 0;
  std::vector<Float3> radiance;                ///< mean radiance per pixel and band
  std::vector<Float3> stderrs;                 ///< standard error of the mean per pixel and band
  std::vector<std::uint8_t> covered;           ///< 1 where the pixel's centre ray meets the mesh
  int samplesPerPixel = 0;                     ///< samples per pixel accumulated
  int passes = 0;                              ///< passes accumulated
  std::int64_t paths = 0;                      ///< paths traced (samples * pixels; each carries 3 bands)
  std::int64_t cappedPaths = 0;                ///< paths ended by maxInteractions
  std::int64_t lostPaths = 0;                  ///< paths ended by an inconsistent hit (mesh not closed)
  std::int64_t interactions = 0;               ///< real collisions, all paths
  std::int64_t nextEvents = 0;                 ///< light connections traced at real collisions
  std::int64_t skippedNextEvents = 0;          ///< light connections ended by their Russian roulette
  std::int64_t depthQueries = 0;               ///< nearest-surface queries for the layer depths
  std::int64_t guidedNextEvents = 0;           ///< extra flights of the next-event MIS (nextEventMis)
  double seconds = 0.0;                        ///< wall-clock time, s
  int threads = 1;                             ///< worker threads used
  Intersector intersector = Intersector::Bvh;  ///< the back end that answered
};

/// Renders the mesh. Errors: an invalid material (validateMaterial), an empty or invalid mesh,
/// UVs missing for per-texel layering, bad settings or lights, an unavailable intersector.
Result<TruthImage> renderPathTraced(const TruthMesh& mesh, const TruthMaterial& material,
                                    std::span<const TruthLight> lights, const TruthCamera& camera,
                                    const PathTraceSettings& settings);

/// The unit direction of the pinhole ray through image position (px, py) in pixels (0..width,
/// 0..height from the top left; the centre of pixel (x, y) is (x + 0.5, y + 0.5)).
Float3 pinholeRayDirection(const TruthCamera& camera, int width, int height, double px, double py);

}  // namespace tissue::truth
