// The soak run (soak_run.h).
#include "tissue/studies/soak_run.h"

#include <algorithm>
#include <array>
#include <cstdio>

#include "json_text.h"
#include "loop_detail.h"
#include "tissue/core/image.h"
#include "tissue/core/process_memory.h"
#include "tissue/core/stopwatch.h"
#include "tissue/gl/objects.h"
#include "tissue/scenario/scenario_run.h"
#include "tissue/scene/session.h"
#include "tissue/studies/loop_report.h"

namespace tissue::studies {
namespace {

constexpr std::array kMethods{render::ShadingMethod::Lit, render::ShadingMethod::Separable,
                              render::ShadingMethod::TextureSpace, render::ShadingMethod::RayMarch,
                              render::ShadingMethod::Parallax};

Result<void> checkConfig(const SoakConfig& o) {
  if (o.frames < 1 || o.sampleEvery < 1 || o.warmupFrames < 0 || o.warmupFrames >= o.frames)
    return Error{"soak: --frames must be >= 1, --sample-every >= 1 and --warmup in [0, frames); got " +
                 std::to_string(o.frames) + ", " + std::to_string(o.sampleEvery) + ", " +
                 std::to_string(o.warmupFrames)};
  if (o.methodEvery < 0 || (o.methodEvery > 0 && o.warmupFrames < o.methodEvery * long(kMethods.size())))
    return Error{"soak: --warmup " + std::to_string(o.warmupFrames) +
                 " must see every method once: give at least " +
                 std::to_string(o.methodEvery * long(kMethods.size())) + " (5 x --method-every)"};
  if (o.width < 16 || o.height < 16 || o.width > 8192 || o.height > 8192)
    return Error{"soak: --width and --height must be 16..8192 pixels"};
  if (o.mapSize < 64) return Error{"soak: --map-size must be >= 64 texels"};
  return {};
}

struct Sample {
  long frame = 0;
  std::int64_t rssKb = 0;
  std::int64_t heapKb = 0;
  gl::ObjectCensus objects;
};

nlohmann::json censusJson(const gl::ObjectCensus& c) {
  return {{"buffers", c.buffers},
          {"vertex_arrays", c.vertexArrays},
          {"textures", c.textures},
          {"framebuffers", c.framebuffers},
          {"renderbuffers", c.renderbuffers},
          {"queries", c.queries},
          {"programs", c.programs},
          {"shaders", c.shaders}};
}

}  // namespace

Result<std::string> soakSession(const SoakConfig& o, const scene::SceneSettings& settings) {
  if (auto ok = checkConfig(o); !ok) return ok.error();
  // Setup: the session, its scenario in a scene on a headless context, GL's own table for the census.
  auto session = scene::loadSession(o.session);
  if (!session) return session.error();
  if (session->frames.empty()) return Error{o.session.string() + ": the session has no frames; record one"};
  auto context = detail::offscreenContext(settings, true);
  if (!context) return context.error();
  auto gl = gl::loadGl((*context)->procAddressFunction());
  if (!gl) return gl.error();
  scene::SceneSettings soakSettings = settings;
  soakSettings.methods.mapSize = o.mapSize;
  soakSettings.methods.lightmap.size = o.mapSize;
  auto scene = detail::makeLoopScene(context->get(), soakSettings);
  if (!scene) return scene.error();
  if (auto added = scene->addOrgan({.scenario = session->scenario}); !added) return added.error();
  if (auto match = scene::checkSessionMatches(*session, *scene->loop(0)); !match) return match.error();

  // Everything the loop keeps is allocated (and its pages touched) before the baseline.
  std::vector<double> frameMs(std::size_t(o.frames), 0.0);
  std::vector<Sample> samples;
  samples.reserve(std::size_t(o.frames / o.sampleEvery + 2));
  Image8 image(o.width, o.height, 4);
  long divergences = 0, nanFrames = 0;
  const std::size_t n = session->frames.size();
  for (long i = 0; i < o.frames; ++i) {
    if (o.methodEvery > 0 && i % o.methodEvery == 0) {
      const auto m = kMethods[std::size_t(i / o.methodEvery) % kMethods.size()];
      if (auto set = scene->setMethod(0, m); !set) return set.error();
    }
    Stopwatch frame;
    auto f = scene->advance(0, scene::sessionInput(*session, std::size_t(i) % n), &image, o.width, o.height);
    if (!f)
      return Error{o.session.string() + ": soak frame " + std::to_string(i) + " (session frame " +
                   std::to_string(std::size_t(i) % n) + "): " + f.error().message};
    frameMs[std::size_t(i)] = frame.elapsedMs();
    divergences += f->simulation.divergenceEvents;
    nanFrames += f->simulation.finite ? 0 : 1;
    if ((i + 1) % o.sampleEvery == 0 || i + 1 == o.warmupFrames) {
      releaseFreeHeap();  // the resident set of what is held, not the allocator's high-water mark
      samples.push_back(
          {i + 1, residentSetKb().value_or(0), heapInUseKb().value_or(0), gl::countLiveObjects(**gl)});
      if (o.onProgress) {
        char line[160];
        std::snprintf(line, sizeof line, "soak: frame %ld of %ld, rss %lld kB, heap %lld kB, %d GL objects",
                      i + 1, o.frames, static_cast<long long>(samples.back().rssKb),
                      static_cast<long long>(samples.back().heapKb), samples.back().objects.total());
        o.onProgress(line);
      }
    }
  }

  // Report: the baseline is the sample at the end of the warm-up.
  const auto base = std::find_if(samples.begin(), samples.end(),
                                 [&](const Sample& s) { return s.frame >= o.warmupFrames; });
  std::int64_t rssMax = base->rssKb;
  int glMin = base->objects.total(), glMax = glMin;
  bool constant = true;
  nlohmann::json list = nlohmann::json::array();
  for (auto s = samples.begin(); s != samples.end(); ++s) {
    list.push_back({{"frame", s->frame},
                    {"rss_kb", s->rssKb},
                    {"heap_kb", s->heapKb},
                    {"gl_objects", s->objects.total()}});
    if (s < base) continue;
    rssMax = std::max(rssMax, s->rssKb);
    glMin = std::min(glMin, s->objects.total());
    glMax = std::max(glMax, s->objects.total());
    constant = constant && s->objects == base->objects;
  }
  const Sample& last = samples.back();
  // A leak raises the floor: the lowest resident set of the last quarter of the samples after
  // the warm-up against the lowest of the first quarter. Single samples sit up to a few MB above
  // the floor while the driver's transient allocations are in flight (the rasteriser's scenes).
  const std::size_t after = std::size_t(samples.end() - base), quarter = std::max<std::size_t>(1, after / 4);
  const auto floorOf = [](auto from, auto to) {
    return std::min_element(from, to, [](const Sample& a, const Sample& b) { return a.rssKb < b.rssKb; })
        ->rssKb;
  };
  const std::int64_t floorEarly = floorOf(base, base + std::ptrdiff_t(quarter));
  const std::int64_t floorLate = floorOf(samples.end() - std::ptrdiff_t(quarter), samples.end());
  const std::int64_t growth = floorLate - floorEarly;
  nlohmann::json j{{"session", o.session.string()},
                   {"frames", o.frames},
                   {"warmup_frames", o.warmupFrames},
                   {"method_every", o.methodEvery},
                   {"width", o.width},
                   {"height", o.height},
                   {"frame_ms", detail::msSummary(frameMs)},
                   {"rss_kb",
                    {{"after_warmup", base->rssKb},
                     {"end", last.rssKb},
                     {"max", rssMax},
                     {"floor_first_quarter", floorEarly},
                     {"floor_last_quarter", floorLate},
                     {"growth", growth},
                     {"peak_growth", rssMax - base->rssKb}}},
                   {"heap_kb", {{"after_warmup", base->heapKb}, {"end", last.heapKb}}},
                   {"gl_objects",
                    {{"after_warmup", base->objects.total()},
                     {"end", last.objects.total()},
                     {"min", glMin},
                     {"max", glMax},
                     {"by_kind", censusJson(base->objects)}}},
                   {"samples", list},
                   {"divergence_events", divergences},
                   {"nan_frames", nanFrames},
                   {"rss_ok", double(growth) <= o.rssBudgetKb},
                   {"gl_ok", constant}};
  return detail::jsonText(j);
}

}  // namespace tissue::studies
