#pragma once
// Private to tissue::studies: the JSON conventions the studies' reports share (nlohmann-json stays
// inside the studies' .cpp files; the public headers hand JSON out as text).

#include <nlohmann/json.hpp>
#include <optional>

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

}  // namespace tissue::studies::detail
