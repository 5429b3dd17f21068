#include "material_file.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "output.h"
#include "tissue/core/atomic_file.h"

namespace tissue::sim_app {

std::filesystem::path materialFileFor(const std::filesystem::path& meshFile) {
  return dataDir() / "materials" / (meshFile.stem().string() + ".json");
}

Result<LayeredMaterial> readLayeredMaterial(const std::filesystem::path& path) {
  auto text = readTextFile(path);
  if (!text) return Error{text.error().message + "; every mesh needs data/materials/<mesh>.json"};
  const auto where = path.string() + ": ";
  try {
    const auto j = nlohmann::json::parse(*text);
    LayeredMaterial m;
    m.name = j.value("name", path.stem().string());
    m.depthScaleMm = j.value("depth_scale_mm", 1.0f);
    m.ior = j.value("ior", 1.3f);
    if (!j.contains("layers") || !j["layers"].is_array() || j["layers"].empty())
      return Error{where + "'layers' must be a non-empty array; see docs/DATA.md"};
    for (std::size_t i = 0; i < j["layers"].size(); ++i) {
      const auto& l = j["layers"][i];
      const auto rgb = [&](const char* key) -> Result<Float3> {
        if (!l.contains(key) || !l[key].is_array() || l[key].size() != 3)
          return Error{where + "layer " + std::to_string(i + 1) + ": '" + key +
                       "' must be [R, G, B] in mm^-1"};
        return Float3{l[key][0].get<float>(), l[key][1].get<float>(), l[key][2].get<float>()};
      };
      auto ss = rgb("sigma_s");
      if (!ss) return ss.error();
      auto st = rgb("sigma_t");
      if (!st) return st.error();
      if (!(st->x > 0 && st->y > 0 && st->z > 0) || st->x < ss->x || st->y < ss->y || st->z < ss->z)
        return Error{where + "layer " + std::to_string(i + 1) +
                     ": need sigma_t > 0 and sigma_t >= sigma_s (mm^-1)"};
      m.layers.push_back({l.value("name", "layer" + std::to_string(i + 1)), *ss, *st, l.value("g", 0.0f)});
    }
    const Float3 t = m.layers.front().sigma_t;
    m.firstLayerMinSigmaT = std::min({t.x, t.y, t.z});
    return m;
  } catch (const nlohmann::json::exception& e) {
    return Error{where + "not valid JSON (" + e.what() + "); fix the file"};
  }
}

}  // namespace tissue::sim_app
