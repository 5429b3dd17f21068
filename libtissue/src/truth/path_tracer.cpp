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
#include "transport.h"

namespace tissue::truth {
namespace {

using V = glm::dvec3;
using optics::detail::RandomStream;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = std::numbers::pi;
using detail::arr;
using detail::PathScratch;
using detail::PathStats;
using detail::sq;
using detail::v3;

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
  const detail::Transport transport(**rays, mesh, material, lights, settings);
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
      PathScratch scratch;
      for (int y = nextRow.fetch_add(1); y < settings.height; y = nextRow.fetch_add(1))
        for (int x = 0; x < settings.width; ++x) {
          const std::size_t pixel = std::size_t(y) * settings.width + x;
          // One stream per pixel and pass: the image does not depend on the thread count.
          RandomStream rng(settings.seed, std::uint64_t(pass) * pixels + pixel);
          scratch.reset(transport.lightCount());
          for (int s = 0; s < settings.samplesPerPass; ++s) {
            const CameraRay r = cameraRays.sample(x, y, rng, settings.jitter);
            Rgb value{0.0, 0.0, 0.0};
            if (settings.spectral) {
              value = transport.trace(r.origin, r.dir, rng, st, scratch);
            } else {
              for (std::size_t b = 0; b < std::size_t(kBands); ++b) {
                Rgb only{0.0, 0.0, 0.0};
                only[b] = 1.0;
                value[b] = transport.trace(r.origin, r.dir, rng, st, scratch, only)[b];
              }
            }
            for (std::size_t band = 0; band < std::size_t(kBands); ++band) {
              acc.sum[3 * pixel + band] += value[band];
              acc.sumSq[3 * pixel + band] += value[band] * value[band];
            }
          }
        }
      PathStats& total = stats[std::size_t(w)];
      total.capped += st.capped;
      total.lost += st.lost;
      total.interactions += st.interactions;
      total.nextEvents += st.nextEvents;
      total.skippedEvents += st.skippedEvents;
      total.depthQueries += st.depthQueries;
      total.guidedEvents += st.guidedEvents;
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
    image.nextEvents += st.nextEvents;
    image.skippedNextEvents += st.skippedEvents;
    image.depthQueries += st.depthQueries;
    image.guidedNextEvents += st.guidedEvents;
  }
  image.paths = std::int64_t(pixels) * image.samplesPerPixel * (settings.spectral ? 1 : kBands);
  image.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return image;
}

}  // namespace tissue::truth
