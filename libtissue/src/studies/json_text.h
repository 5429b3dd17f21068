#pragma once
// Private to tissue::studies: the JSON conventions the studies' reports share (nlohmann-json stays
// inside the studies' .cpp files; the public headers hand JSON out as text).

#include <nlohmann/json.hpp>
#include <optional>

#include "tissue/scene/budget.h"

namespace tissue::studies::detail {

/// The value, or null when there is none.
template <class T>
nlohmann::json optionalJson(const std::optional<T>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

/// The text a report file holds: indented by 2, ending in a newline.
inline std::string jsonText(const nlohmann::json& value) {
  return value.dump(2) + "\n";
}

/// What the quality controller chose for one organ (scene::BudgetChoice), as the reports write it.
inline nlohmann::json budgetChoiceJson(const scene::BudgetChoice& c) {
  return {{"method", c.method},
          {"setting", c.setting},
          {"footprint_px", c.footprintPx},
          {"view", c.view},
          {"view_angle_deg", c.viewAngleDeg},
          {"predicted_ms", c.predictedMs},
          {"expected_rel_rms", c.expectedRelRms},
          {"fallback", c.fallback},
          {"planes", c.mesh.planes},
          {"tangents", c.mesh.tangents}};
}

}  // namespace tissue::studies::detail
