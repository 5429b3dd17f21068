// The speed-accuracy atlas (atlas.h): the organ's frames, the truth of each (cached), every
// method and setting rendered, timed, read back as linear radiance and scored.
#include "tissue/studies/atlas.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>

#include "atlas_detail.h"
#include "json_text.h"
#include "tissue/core/statistics.h"
#include "tissue/render/shading.h"
#include "tissue/scene/budget.h"
#include "tissue/scene/organ_loop.h"
#include "tissue/scene/organ_methods.h"
#include "tissue/scene/truth_view.h"
#include "tissue/studies/frame_radiance.h"

namespace tissue::studies {
namespace {

using render::ShadingMethod;

using Setting = AtlasSetting;

}  // namespace

render::Light detail::lightBesideLens(const render::Camera& camera, float rightMm, float upMm,
                                      float forwardMm) {
  const Float3 f = normalize(camera.target - camera.eye);
  const Float3 r = normalize(cross(f, camera.up));
  const Float3 u = cross(r, f);
  render::Light l;
  l.positionMm = camera.eye + rightMm * r + upMm * u + forwardMm * f;
  l.castsShadows = true;
  return l;
}

std::vector<AtlasSetting> atlasSettings(bool quick) {
  std::vector<Setting> out;
  out.push_back({ShadingMethod::Lit, "default", {}});
  // The quality controller's small-footprint fallback (Green 2004's wrap; Unreal Substrate's
  // Wrap tier), scored like every other setting so its table has the row's own errors.
  out.push_back({ShadingMethod::Lit, std::string(quality::kWrapSetting), {.litWrapFromOptics = true}});
  const std::vector<std::string> kernels =
      quick ? std::vector<std::string>{"preintegrated", "jimenez"}
            : std::vector<std::string>{"svd", "preintegrated", "guided", "manual", "deon", "jimenez"};
  const std::vector<int> taps = quick ? std::vector<int>{7, 17} : std::vector<int>{7, 11, 17, 25};
  for (const std::string& k : kernels)
    for (int t : taps) {
      scene::MethodChoices c;
      c.kernel = k;
      c.taps = t;
      out.push_back({ShadingMethod::Separable, k + "-" + std::to_string(t), c});
    }
  for (int g : quick ? std::vector<int>{2, 6} : std::vector<int>{2, 4, 6})
    for (bool opt : {true, false}) {
      if (quick && !opt && g != 6) continue;
      scene::MethodChoices c;
      c.gaussians = g;
      c.cull = c.clip = c.depthSize = opt;
      c.mapSize = quick ? 512 : 1024;
      out.push_back({ShadingMethod::TextureSpace, std::to_string(g) + "g-" + (opt ? "opt" : "plain"), c});
    }
  for (int n : quick ? std::vector<int>{10, 50} : std::vector<int>{10, 25, 50, 100}) {
    scene::MethodChoices c;
    c.samples = n;
    c.adaptive = false;
    out.push_back({ShadingMethod::RayMarch, std::to_string(n), c});
  }
  {
    scene::MethodChoices c;
    c.samples = 100;
    c.adaptive = true;
    out.push_back({ShadingMethod::RayMarch, "adaptive-100", c});
  }
  out.push_back({ShadingMethod::Parallax, "default", {}});
  return out;
}

namespace {

// One frame: its name, camera, lights and whether the organ is poked.
struct Frame {
  std::string name;
  render::Camera camera;
  std::vector<render::Light> lights;
  bool poked = false;
  /// The truth's time budget over AtlasConfig::truthSeconds (full atlas only): the backlit frame's
  /// light is about 1e-4 of the others', so its samples are mostly zero and it needs more of them;
  /// the close-up covers ~5x the others' organ pixels (5391 of 6912 at 96 x 72, against ~1070), so
  /// at one time it would get a fifth of their samples per pixel, and it is the frame that decides
  /// the close organ's method and kernel (quality::QualityTable, issue 16).
  double truthTimeFactor = 1.0;
};

render::Light keyLight(const Bounds3& b) {
  render::Light l;  // the main job's key lamp: above, right and in front of the field
  const Float3 c = b.centre();
  l.positionMm = {c.x + 150.0f, c.y + 200.0f, b.hi.z + 300.0f};
  l.castsShadows = true;
  return l;
}

// The frames of the atlas for the organ's rest shape (`rays` over it).
Result<std::vector<Frame>> makeFrames(const scene::OrganAssets& organ, const truth::RayMesh& rays,
                                      float aspect) {
  const Bounds3 b = organ.bounds;
  std::vector<Frame> frames;
  const render::Camera framed = render::frameBoundingBox(b.lo, b.hi, aspect);
  frames.push_back({"rest", framed, {keyLight(b)}, false});
  frames.push_back({"poked", framed, {keyLight(b)}, true});
  // Oblique: the organ seen at about 45 degrees (a laparoscope looking down into the field through
  // its port), on the grazing frame's side: with rest (~25), low (~62) and grazing (~80) it samples
  // the error's dependence on the view angle, which the quality controller interpolates
  // (quality::expectedSquaredError). Four times the truth time: the bench's organs are seen at
  // 43-64 degrees (budget_bench.cpp), so this frame's and the low frame's lead differences are
  // the controller's for most organs in view.
  const render::Camera oblique = render::frameBoundingBox(b.lo, b.hi, aspect, {-1.0f, -0.1f, -1.0f});
  // Close-up: a third of the distance to the surface point under the oblique view's centre, the
  // laparoscope's close-up of the tissue it works on (seen through the port at about 45 degrees,
  // as the oblique frame; the controller moves its error along the angle from there).
  const Float3 toward = normalize(oblique.target - oblique.eye);
  const auto centreHit = rays.intersect({oblique.eye.x, oblique.eye.y, oblique.eye.z},
                                        {toward.x, toward.y, toward.z}, 0.0, 1e30);
  if (!centreHit) return Error{"atlas: the oblique camera's centre ray misses the organ"};
  const Float3 hit = oblique.eye + float(centreHit->t) * toward;
  render::Camera close = oblique;
  close.target = hit;
  close.eye = hit - float(centreHit->t / 3.0) * toward;
  close.nearMm = 0.5f;
  frames.push_back({"close-up", close, {detail::lightBesideLens(close)}, false, 6.0});
  frames.push_back({"oblique", oblique, {detail::lightBesideLens(oblique)}, false, 4.0});
  // Low: the laparoscope low over the field, the organ's top at about 28 degrees (a view angle of
  // ~62): between the oblique and grazing frames, where the ray march's lead turns (its grazing
  // error is the highest of all methods, its oblique error among the lowest).
  const render::Camera low = render::frameBoundingBox(b.lo, b.hi, aspect, {-1.0f, -0.1f, -0.53f});
  frames.push_back({"low", low, {detail::lightBesideLens(low)}, false, 4.0});
  // Far: the low view from 2.5 times the distance (the organ on ~2-3 % of the image, ~150 of
  // 96 x 72 pixels), under the light beside the lens, now nearly along the view (2-4 degrees off
  // it, as for the budget bench's far organs): small organs at the edge of the field, where each
  // pixel spans millimetres, the diffusion is below a pixel and what differs between the methods
  // is the angular shape of the reflection under the scope's own light (single scattering's
  // backscatter). The table does not use its errors yet (the controller's classes are by angle);
  // its timings give the cost lines a small-footprint point (quality::QualityTable).
  render::Camera far = low;
  far.eye = low.target + 2.5f * (low.eye - low.target);
  far.nearMm = 2.5f * low.nearMm;
  far.farMm = 2.5f * low.farMm;
  frames.push_back({"far", far, {detail::lightBesideLens(far)}, false});
  // Grazing: the organ seen nearly edge-on (its top surface at about 10 degrees).
  const render::Camera grazing = render::frameBoundingBox(b.lo, b.hi, aspect, {-1.0f, -0.1f, -0.18f});
  frames.push_back({"grazing", grazing, {detail::lightBesideLens(grazing)}, false});
  // A thin part lit from behind: of the framed view's rays on a 48 x 36 grid that meet the organ
  // facing it (cosine > 0.5), the one whose way through the organ is shortest (but >= 1 mm),
  // seen from a third of the distance, with a directional light from the far side travelling
  // towards the camera (the renderer's shadowed lamp sees only the back).
  const Float3 forward = normalize(framed.target - framed.eye);
  const Float3 right = normalize(cross(forward, framed.up));
  const Float3 up = cross(right, forward);
  const float tanHalf = std::tan(framed.verticalFovDeg * 3.14159265f / 360.0f);
  double thinnest = 1e30, thinDistance = 0.0;
  Float3 thinPoint{}, thinDir{};
  for (int j = 0; j < 36; ++j)
    for (int i = 0; i < 48; ++i) {
      const float sx = (2.0f * (float(i) + 0.5f) / 48.0f - 1.0f) * tanHalf * aspect;
      const float sy = (1.0f - 2.0f * (float(j) + 0.5f) / 36.0f) * tanHalf;
      const Float3 d = normalize(forward + sx * right + sy * up);
      const auto entry =
          rays.intersect({framed.eye.x, framed.eye.y, framed.eye.z}, {d.x, d.y, d.z}, 0.0, 1e30);
      if (!entry) continue;
      const Triangle& t = organ.mesh.triangles[entry->triangle];
      const Float3 n = normalize(cross(organ.mesh.positions[t[1]] - organ.mesh.positions[t[0]],
                                       organ.mesh.positions[t[2]] - organ.mesh.positions[t[0]]));
      if (dot(n, d) > -0.5f) continue;
      const Float3 p = framed.eye + float(entry->t + 0.01) * d;
      const auto exit = rays.intersect({p.x, p.y, p.z}, {d.x, d.y, d.z}, 0.0, 1e30);
      if (!exit || exit->t < 1.0 || exit->t >= thinnest) continue;
      thinnest = exit->t;
      thinDistance = entry->t;
      thinPoint = framed.eye + float(entry->t) * d;
      thinDir = d;
    }
  if (thinnest > 1e29) return Error{"atlas: found no thin part of the organ in view"};
  render::Camera back = framed;
  back.target = thinPoint;
  back.eye = thinPoint - float(thinDistance / 3.0) * thinDir;
  back.nearMm = 0.5f;
  render::Light behind;
  behind.type = render::LightType::Directional;
  behind.direction = -1.0f * thinDir;  // from the far side, towards the camera
  behind.castsShadows = true;
  frames.push_back({"backlit", back, {behind}, false, 3.0});
  return frames;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

}  // namespace

Result<AtlasResult> runAtlas(render::Renderer& renderer, const AtlasConfig& configIn) {
  AtlasConfig config = configIn;
  if (config.quick) {
    config.width = std::min(config.width, 96);
    config.height = std::min(config.height, 72);
    config.truthSpp = std::min(config.truthSpp, 64);
    config.truthSeconds = std::min(config.truthSeconds, 5.0);
    config.frames = std::min(config.frames, 2);
  }
  const int w = config.width, h = config.height;
  const bool artists = config.artistTerms;
  // 1 the organ, its loop (the scenario's poke), its textures and the frames.
  auto loaded = scene::loadSimulatedOrgan(config.organ, config.scene);
  if (!loaded) return loaded.error();
  const scene::OrganAssets& organ = loaded->assets;
  scene::OrganLoopConfig loopConfig;
  loopConfig.planes = organ.planes;
  loopConfig.uploadPlanes = true;
  loopConfig.drawInstrument = false;
  auto loop = scene::OrganLoop::create(loaded->scenario, organ.mesh, loopConfig);
  if (!loop) return loop.error();
  auto mesh = loop->attach(renderer);
  if (!mesh) return mesh.error();
  auto textures = scene::uploadOrganTextures(renderer, organ);
  if (!textures) return textures.error();
  auto restRays = truth::makeRayMesh(organ.mesh.positions, organ.mesh.triangles);
  if (!restRays) return restRays.error();
  auto frames = makeFrames(organ, **restRays, float(w) / float(h));
  if (!frames) return frames.error();
  const std::vector<Setting> settings = atlasSettings(config.quick);

  AtlasResult result;
  Report& report = result.output.report;
  std::vector<std::pair<std::string, std::string>> skipped;
  std::vector<Float3> positions = organ.mesh.positions;
  for (const Frame& frame : *frames) {
    // 2 the poke: the scenario runs until its push peaks (no grasp), as the main job's poked frame.
    if (frame.poked) {
      double peak = 0.0;
      for (int f = 0; f < 900; ++f) {
        auto step = loop->step();
        if (!step) return step.error();
        const auto& m = step->simulation;
        if (m.grasped == 0) peak = std::max(peak, m.forceMagnitudeN);
        if (peak > 0.2 && m.forceMagnitudeN < 0.9 * peak) break;
      }
      if (auto up = loop->upload(); !up) return up.error();
      const std::span<const Float3> geometric = loop->geometricPositions();
      for (std::size_t i = 0; i < positions.size(); ++i)
        positions[i] = geometric[organ.mesh.geometricIndex[i]];
    }
    render::Scene scene;
    scene.camera = frame.camera;
    scene.lights = frame.lights;
    scene.exposure = 1.0f;
    // 3 the truth of the frame, from the cache when it has it.
    truth::PathTraceSettings ts;
    ts.width = w;
    ts.height = h;
    ts.samplesPerPass = std::max(2, config.truthSpp / 16);
    ts.passes = std::max(1, config.truthSpp / ts.samplesPerPass);
    ts.threads = config.threads;
    ts.seed = 13;
    const double budget = config.truthSeconds * (config.quick ? 1.0 : frame.truthTimeFactor);
    ts.onPass = [budget, &config, &frame](const truth::PathTraceProgress& p) {
      if (config.onProgress) {
        char line[160];
        std::snprintf(line, sizeof line, "truth %s: %d spp, %.1f s, mean relative stderr %.3f",
                      frame.name.c_str(), p.samplesPerPixel, p.seconds, p.meanRelativeStderr);
        config.onProgress(line);
      }
      return p.seconds < budget;
    };
    AtlasTruth at;
    at.frame = frame.name;
    // The view angle as the scene's budget sees an organ (its box's thinnest axis against the ray
    // to its centre), so that the controller's angles and the table's are one measure.
    at.viewAngleDeg = scene::organView(organ.bounds, kIdentity4, frame.camera, w, h).viewAngleDeg;
    auto material = scene::truthMaterialOf(organ);
    if (!material) return material.error();
    const std::uint64_t key = detail::truthKey(positions, organ.mesh, *material, scene, ts, budget);
    const std::filesystem::path cacheFile = config.cacheDir.empty()
                                                ? std::filesystem::path{}
                                                : config.cacheDir / detail::truthCacheName(frame.name, key);
    std::optional<truth::TruthImage> truthImage;
    if (!cacheFile.empty()) truthImage = detail::readTruthCache(cacheFile);
    if (truthImage) {
      at.fromCache = true;
      at.cachedMs = 1e3 * truthImage->seconds;
    } else {
      auto traced = scene::renderTruth(organ, positions, scene, ts);
      if (!traced) return traced.error();
      truthImage = std::move(*traced);
      at.ms = 1e3 * truthImage->seconds;
      at.cachedMs = at.ms;
      if (!cacheFile.empty())
        if (auto ok = detail::writeTruthCache(cacheFile, *truthImage); !ok) return ok.error();
    }
    const truth::TruthImage& T = *truthImage;
    at.samplesPerPixel = T.samplesPerPixel;
    at.noiseRelRms = truthNoiseRelRms(T);
    for (std::uint8_t c : T.covered)
      at.organPixels += c;
    result.truths.push_back(at);
    std::vector<Float3> truthLinear(T.radiance.begin(), T.radiance.end());
    report.images.push_back({"truth_" + frame.name + ".png", toneMapped(truthLinear, w, h)});
    // 4 every method and setting: timed, read back, scored.
    if (config.onProgress)
      config.onProgress("frame " + frame.name + ": " + std::to_string(settings.size()) + " settings" +
                        (at.fromCache ? " (truth from the cache)" : ""));
    std::map<std::string, std::pair<double, Image8>> bestError;  // per method: rel RMS, error image
    const std::size_t firstRow = result.rows.size();
    std::vector<std::vector<Float3>> images;  // this frame's rows' linear radiance
    for (const Setting& s : settings) {
      const std::string method(render::shadingMethodName(s.method));
      auto ms = scene::organMethod(s.method, organ, *textures, s.choices);
      if (!ms) {
        skipped.push_back({method + " " + s.name + " (" + frame.name + ")", ms.error().message});
        continue;
      }
      // No ambient and no normal map (AtlasConfig::artistTerms): the truth is lit by the frame's
      // lights alone and reflects off the mesh's own shape.
      scene.objects = {scene::organObject(
          *mesh, *textures, *ms, scene::surfaceMaterialOf(organ, artists ? config.scene.ambient : Float3{}))};
      if (!artists || !config.scene.normalMaps) scene.objects[0].normalMap = {};
      std::vector<double> times;
      for (int f = 0; f <= config.frames; ++f) {
        const auto start = std::chrono::steady_clock::now();
        auto img = renderer.renderImage(scene, w, h);
        if (!img) return Error{"atlas: " + method + " " + s.name + ": " + img.error().message};
        if (f > 0)  // the first frame warms up (shaders, maps)
          times.push_back(
              std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
      }
      auto linear = lastFrameRadiance(renderer);
      if (!linear) return linear.error();
      const AtlasScore score = scoreAgainstTruth(truthLinear, *linear, T.covered);
      result.rows.push_back({method, s.name, frame.name, median(times), score.relRms, score.psnrDb,
                             score.gain, score.shapeRelRms});
      auto it = bestError.find(method);
      if (it == bestError.end() || score.relRms < it->second.first)
        bestError[method] = {score.relRms, errorImage(truthLinear, *linear, T.covered, w, h)};
      images.push_back(std::move(*linear));
    }
    // Each row against the frame's best, paired on the same truth.
    std::size_t best = firstRow;
    for (std::size_t k = firstRow; k < result.rows.size(); ++k)
      if (result.rows[k].relRms < result.rows[best].relRms) best = k;
    for (std::size_t k = firstRow; k < result.rows.size(); ++k) {
      const ErrorDifference d =
          errorDifference(truthLinear, T.stderrs, images[k - firstRow], images[best - firstRow], T.covered);
      result.rows[k].squaredVsBest = d.squared;
      result.rows[k].squaredVsBestStderr = d.squaredStderr;
      result.rows[k].worseThanBest = d.bLower();
    }
    for (auto& [method, e] : bestError)
      report.images.push_back({"error_" + frame.name + "_" + method + ".png", std::move(e.second)});
  }
  scene::destroyOrganTextures(renderer, *textures);
  loop->detach();
  detail::writeAtlasReport(result, config, skipped);
  return result;
}

}  // namespace tissue::studies
