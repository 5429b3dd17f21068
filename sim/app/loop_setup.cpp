#include "loop_setup.h"

#include <cmath>

#include "gl_environment.h"
#include "organ_data.h"
#include "output.h"
#include "tissue/core/statistics.h"

namespace tissue::sim_app {

Result<scene::Scene> makeLoopScene(const context::GlContext* context) {
  scene::SceneSettings settings = dataSceneSettings();
  settings.renderer.samples = 0;  // 4x MSAA of three float targets is llvmpipe's heaviest pass
  settings.gl = context != nullptr;
  return scene::Scene::create(context ? context->procAddressFunction() : gl::GetProcAddressFn{}, settings);
}

context::ContextRequest offscreenRequest() {
  context::ContextRequest request;
  request.width = request.height = 16;
  return request;
}

double rounded(double x) {
  if (x == 0.0 || !std::isfinite(x)) return x;
  const double scale = std::pow(10.0, 2 - std::floor(std::log10(std::abs(x))));
  return std::round(x * scale) / scale;
}

nlohmann::json phaseReport(const scene::LoopPhaseSamples& samples) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& [name, values] : samples.phases) {
    const auto s = summarizeSamples(values);
    j.push_back({{"phase", name},
                 {"median_ms", rounded(s.median)},
                 {"p99_ms", rounded(s.p99)},
                 {"max_ms", rounded(s.max)}});
  }
  return j;
}

}  // namespace tissue::sim_app
