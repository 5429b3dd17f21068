// The trainee's loop's figures for the reports (loop_report.h).
#include "tissue/studies/loop_report.h"

#include <cmath>

#include "json_text.h"
#include "loop_detail.h"
#include "tissue/context/headless_context.h"
#include "tissue/core/statistics.h"
#include "tissue/scenario/scenario_run.h"

namespace tissue::studies {
namespace detail {

nlohmann::json msSummary(const std::vector<double>& ms) {
  const auto s = summarizeSamples(ms);
  return {{"median", threeDigits(s.median)}, {"p99", threeDigits(s.p99)}, {"max", threeDigits(s.max)}};
}

nlohmann::json loopPhases(const scene::LoopPhaseSamples& samples) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& [name, values] : samples.phases) {
    const auto s = summarizeSamples(values);
    j.push_back({{"phase", name},
                 {"median_ms", threeDigits(s.median)},
                 {"p99_ms", threeDigits(s.p99)},
                 {"max_ms", threeDigits(s.max)}});
  }
  return j;
}

nlohmann::json instrument(const scene::LoopRecord& r) {
  const auto s = scenario::summarize(r.frames);
  nlohmann::json forces = nlohmann::json::array();
  for (const auto& f : r.frames)
    forces.push_back({f.forceN.x, f.forceN.y, f.forceN.z});
  return {{"frames", s.frames},
          {"nan_frames", s.nanFrames},
          {"divergence_events", s.divergenceEvents},
          {"max_contact_force_N", s.maxForceN},
          {"mean_contact_force_N", s.meanForceN},
          {"max_push_N", r.maxPushN},
          {"max_pull_N", r.maxPullN},
          {"poked_frame", r.pokedFrame},
          {"lifted_frame", r.liftedFrame},
          {"ms_per_frame",
           {{"integrate", s.meanIntegrateMs}, {"contact", s.meanContactMs}, {"check", s.meanCheckMs}}},
          {"contact_force_N_per_frame", forces}};
}

nlohmann::json passTimings(const render::RenderTimings& timings) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& p : timings.passes)
    list.push_back({{"name", p.name}, {"cpu_ms", p.cpuMs}, {"gpu_ms", p.gpuMs}, {"object", p.object}});
  return list;
}

Result<scene::Scene> makeLoopScene(const context::GlContext* context, scene::SceneSettings settings) {
  settings.renderer.samples = 0;  // 4x MSAA of three float targets is llvmpipe's heaviest pass
  settings.gl = context != nullptr;
  return scene::Scene::create(context ? context->procAddressFunction() : gl::GetProcAddressFn{}, settings);
}

Result<std::unique_ptr<context::GlContext>> offscreenContext(const scene::SceneSettings& settings, bool log) {
  context::ContextRequest request = settings.context;
  request.width = request.height = 16;
  context::HeadlessOptions headless = settings.headless;
  headless.log = log;
  return context::createHeadlessContext(request, headless);
}

}  // namespace detail

double threeDigits(double x) {
  if (x == 0.0 || !std::isfinite(x)) return x;
  const double scale = std::pow(10.0, 2 - std::floor(std::log10(std::abs(x))));
  return std::round(x * scale) / scale;
}

std::string loopPhasesJson(const scene::LoopPhaseSamples& samples) {
  return detail::loopPhases(samples).dump();
}

Table loopPhasesTable(const scene::LoopPhaseSamples& samples) {
  Table table{.header = {"phase", "median", "p99", "max"}, .rows = {}};
  // The cells as the JSON report writes the same figures (nlohmann's shortest round trip).
  for (const auto& p : detail::loopPhases(samples))
    table.rows.push_back(
        {p["phase"].get<std::string>(), p["median_ms"].dump(), p["p99_ms"].dump(), p["max_ms"].dump()});
  return table;
}

std::string instrumentJson(const scene::LoopRecord& record) {
  return detail::instrument(record).dump();
}

std::string passTimingsJson(const render::RenderTimings& timings) {
  return detail::passTimings(timings).dump();
}

}  // namespace tissue::studies
