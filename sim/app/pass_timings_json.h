#pragma once
/// \file
/// The renderer's per-pass timings as JSON: [{name, cpu_ms, gpu_ms}, ...] in pass order
/// (gpu_ms -1 when timers are off or the driver's value is impossible).

#include <nlohmann/json.hpp>

#include "tissue/render/renderer.h"

namespace tissue::sim_app {

/// [{name, cpu_ms, gpu_ms}] of the last frame's passes, ms.
inline nlohmann::json passTimingsJson(const render::RenderTimings& timings) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& p : timings.passes)
    list.push_back({{"name", p.name}, {"cpu_ms", p.cpuMs}, {"gpu_ms", p.gpuMs}});
  return list;
}

}  // namespace tissue::sim_app
