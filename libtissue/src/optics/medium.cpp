// Layered media: validation and the medium file format (medium.h).
#include "tissue/optics/medium.h"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace tissue::optics {

namespace {

// The first range problem of `m` as "key 'layers[i].field' must ...", or empty.
std::string findProblem(const LayeredMedium& m) {
  auto bad = [](const std::string& key, const std::string& what) { return "key '" + key + "' " + what; };
  if (!(m.ambientAbove >= 1.0)) return bad("ambient_n", "must be >= 1");
  if (!(m.ambientBelow >= 1.0)) return bad("ambient_n_below", "must be >= 1");
  if (m.layers.empty()) return bad("layers", "must hold at least one layer");
  for (std::size_t i = 0; i < m.layers.size(); ++i) {
    const Layer& l = m.layers[i];
    const std::string key = "layers[" + std::to_string(i) + "].";
    if (!(l.n >= 1.0)) return bad(key + "n", "must be >= 1");
    if (!(l.mua >= 0.0) || !std::isfinite(l.mua)) return bad(key + "mua", "must be finite and >= 0 (mm^-1)");
    if (!(l.mus >= 0.0) || !std::isfinite(l.mus)) return bad(key + "mus", "must be finite and >= 0 (mm^-1)");
    if (!(std::abs(l.g) < 1.0)) return bad(key + "g", "must lie in (-1, 1)");
    if (!(l.thickness > 0.0)) return bad(key + "thickness", "must be > 0 mm or \"inf\"");
    const bool last = i + 1 == m.layers.size();
    if (std::isinf(l.thickness) && !last)
      return bad(key + "thickness", "may be \"inf\" only in the last layer");
    if (std::isinf(l.thickness) && l.mua + l.mus <= 0.0)
      return bad(key + "mus", "must be > 0 (or mua > 0) in an infinitely thick layer");
  }
  return {};
}

}  // namespace

Result<void> validateMedium(const LayeredMedium& m) {
  if (const auto problem = findProblem(m); !problem.empty()) return Error{"medium: " + problem};
  return {};
}

double specularReflectance(const LayeredMedium& medium) {
  if (medium.layers.empty()) return 0.0;
  const double r = (medium.ambientAbove - medium.layers[0].n) / (medium.ambientAbove + medium.layers[0].n);
  return r * r;
}

namespace {

using nlohmann::json;

// Reads `obj[key]` as a number into `out`; errors name the file and the key path.
Result<void> readNumber(const json& obj, const std::string& key, const std::string& path,
                        const std::string& source, double& out) {
  const auto it = obj.find(key);
  if (it == obj.end()) return Error{"medium file " + source + ": key '" + path + "' is missing; add it"};
  if (!it->is_number()) return Error{"medium file " + source + ": key '" + path + "' must be a number"};
  out = it->get<double>();
  return {};
}

Result<Layer> parseLayer(const json& j, std::size_t index, const std::string& source) {
  const std::string prefix = "layers[" + std::to_string(index) + "]";
  if (!j.is_object()) return Error{"medium file " + source + ": key '" + prefix + "' must be an object"};
  for (const auto& [key, value] : j.items()) {
    if (key != "n" && key != "mua" && key != "mus" && key != "g" && key != "thickness")
      return Error{"medium file " + source + ": unknown key '" + prefix + "." + key +
                   "'; a layer has n, mua, mus, g, thickness"};
  }
  Layer layer;
  for (auto [key, field] :
       {std::pair{"n", &layer.n}, {"mua", &layer.mua}, {"mus", &layer.mus}, {"g", &layer.g}}) {
    if (auto ok = readNumber(j, key, prefix + "." + key, source, *field); !ok) return ok.error();
  }
  const auto t = j.find("thickness");
  if (t == j.end())
    return Error{"medium file " + source + ": key '" + prefix + ".thickness' is missing; add it"};
  if (t->is_string() && t->get<std::string>() == "inf")
    layer.thickness = kInfiniteThickness;
  else if (t->is_number())
    layer.thickness = t->get<double>();
  else
    return Error{"medium file " + source + ": key '" + prefix +
                 ".thickness' must be a number (mm) or \"inf\""};
  return layer;
}

}  // namespace

Result<LayeredMedium> parseMediumJson(const std::string& text, const std::string& source) {
  const json j = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) return Error{"medium file " + source + ": not valid JSON"};
  if (!j.is_object()) return Error{"medium file " + source + ": the top level must be an object"};
  for (const auto& [key, value] : j.items()) {
    if (key != "ambient_n" && key != "ambient_n_below" && key != "layers")
      return Error{"medium file " + source + ": unknown key '" + key +
                   "'; expected ambient_n, ambient_n_below, layers"};
  }
  LayeredMedium m;
  if (auto ok = readNumber(j, "ambient_n", "ambient_n", source, m.ambientAbove); !ok) return ok.error();
  m.ambientBelow = m.ambientAbove;
  if (j.contains("ambient_n_below")) {
    if (auto ok = readNumber(j, "ambient_n_below", "ambient_n_below", source, m.ambientBelow); !ok)
      return ok.error();
  }
  const auto layers = j.find("layers");
  if (layers == j.end() || !layers->is_array() || layers->empty())
    return Error{"medium file " + source + ": key 'layers' must be a non-empty array of layers"};
  for (std::size_t i = 0; i < layers->size(); ++i) {
    auto layer = parseLayer((*layers)[i], i, source);
    if (!layer) return layer.error();
    m.layers.push_back(*layer);
  }
  if (const auto problem = findProblem(m); !problem.empty())
    return Error{"medium file " + source + ": " + problem};
  return m;
}

Result<LayeredMedium> loadMediumFile(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) return Error{"medium file " + path.string() + ": cannot be read; check the path"};
  std::ostringstream text;
  text << in.rdbuf();
  return parseMediumJson(text.str(), path.string());
}

}  // namespace tissue::optics
