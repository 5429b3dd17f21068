// The one reader of data/materials/*.json (material_file.h). nlohmann-json stays in this file.
#include "tissue/scene/material_file.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "tissue/core/atomic_file.h"

namespace tissue::scene {
namespace {

using nlohmann::json;

/// `key` of `object` as [R, G, B] numbers, or an error naming `where` and the unit.
Result<Float3> readRgb(const json& object, const char* key, const std::string& where) {
  const auto it = object.find(key);
  if (it == object.end() || !it->is_array() || it->size() != 3 || !(*it)[0].is_number() ||
      !(*it)[1].is_number() || !(*it)[2].is_number())
    return Error{where + ": '" + key + "' must be [R, G, B] in mm^-1"};
  return Float3{(*it)[0].get<float>(), (*it)[1].get<float>(), (*it)[2].get<float>()};
}

Result<MaterialLayer> readLayer(const json& l, const std::string& where) {
  if (!l.is_object()) return Error{where + ": must be an object with sigma_s, sigma_t and g"};
  MaterialLayer layer;
  auto s = readRgb(l, "sigma_s", where);
  if (!s) return s.error();
  auto t = readRgb(l, "sigma_t", where);
  if (!t) return t.error();
  layer.sigmaS = *s;
  layer.sigmaT = *t;
  const bool positive = t->x > 0 && t->y > 0 && t->z > 0 && s->x >= 0 && s->y >= 0 && s->z >= 0;
  if (!positive || t->x < s->x || t->y < s->y || t->z < s->z)
    return Error{where +
                 ": need sigma_t > 0 and sigma_t >= sigma_s >= 0 (mm^-1; sigma_a = sigma_t - sigma_s)"};
  const auto g = l.find("g");
  if (g == l.end() || !g->is_number()) return Error{where + ": 'g' (the mean cosine, -1 < g < 1) is missing"};
  layer.g = g->get<float>();
  if (!(layer.g > -1.0f && layer.g < 1.0f)) return Error{where + ": 'g' must lie in (-1, 1)"};
  layer.name = l.value("name", std::string());
  layer.source = l.value("source", std::string());
  return layer;
}

/// `relative` in the first root that holds it; empty and an error naming the roots otherwise.
Result<std::filesystem::path> findTexture(const std::string& relative,
                                          const std::vector<std::filesystem::path>& roots,
                                          const std::string& where) {
  const std::filesystem::path p(relative);
  if (p.is_absolute()) {
    if (std::filesystem::exists(p)) return p;
    return Error{where + ": " + p.string() + " does not exist"};
  }
  std::string searched;
  for (const auto& root : roots) {
    if (const auto full = root / p; std::filesystem::exists(full)) return full;
    searched += (searched.empty() ? "" : ", ") + root.string();
  }
  return Error{
      where + ": " + relative + " is in none of " + searched +
      " (texture paths are relative to the data folder; build target tissue_data for the 1024^2 ones)"};
}

}  // namespace

Result<MaterialFile> readMaterialFile(const std::filesystem::path& file, const MaterialFileOptions& options) {
  auto text = readTextFile(file);
  if (!text)
    return Error{"material file " + file.string() +
                 ": cannot be read; give an existing data/materials/<organ>.json (docs/DATA.md)"};
  const json doc = json::parse(*text, nullptr, false);
  const std::string where = "material file " + file.string();
  if (doc.is_discarded() || !doc.is_object())
    return Error{where + ": not a JSON object; see docs/DATA.md for the schema"};
  MaterialFile m;
  m.file = file;
  m.name = doc.value("name", file.stem().string());
  for (const auto& [key, value] : {std::pair{"depth_scale_mm", &m.depthScaleMm}, std::pair{"ior", &m.ior}}) {
    if (!doc.contains(key)) continue;
    if (!doc[key].is_number() || !(doc[key].get<float>() > 0.0f))
      return Error{where + ": '" + key + "' must be a positive number"};
    *value = doc[key].get<float>();
  }
  const auto layers = doc.find("layers");
  if (layers == doc.end() || !layers->is_array() || layers->empty())
    return Error{where + ": 'layers' must be a non-empty array of {sigma_s, sigma_t, g}"};
  for (std::size_t i = 0; i < layers->size(); ++i) {
    auto layer = readLayer((*layers)[i], where + ": layers[" + std::to_string(i) + "]");
    if (!layer) return layer.error();
    if (layer->name.empty()) layer->name = "layer" + std::to_string(i + 1);
    m.layers.push_back(std::move(*layer));
  }
  std::vector<std::filesystem::path> roots = options.textureRoots;
  if (roots.empty()) roots.push_back(file.parent_path().parent_path());
  const json textures = doc.value("textures", json::object());
  if (!textures.is_object()) return Error{where + ": 'textures' must be an object of relative paths"};
  for (const auto& [key, slot] :
       {std::pair{"subsurface", &m.textures.subsurface}, std::pair{"base_color", &m.textures.baseColor},
        std::pair{"normal_map", &m.textures.normalMap}, std::pair{"opacity", &m.textures.opacity},
        std::pair{"inner_base", &m.textures.innerBase}}) {
    if (!textures.contains(key)) continue;
    if (!textures[key].is_string()) return Error{where + ": 'textures." + key + "' must be a path"};
    auto found = findTexture(textures[key].get<std::string>(), roots, where + ": 'textures." + key + "'");
    if (!found) return found.error();
    *slot = std::move(*found);
  }
  return m;
}

MaterialFile defaultMaterial() {
  MaterialFile m;
  m.name = "default-organ";
  MaterialLayer organ;  // the defaults of MaterialLayer: François et al. 2006 Table 1, organs
  organ.name = "organ";
  organ.source = "François et al. 2006, 'Subsurface Texture Mapping', Table 1: organs";
  m.layers = {organ};
  return m;
}

optics::ScatteringMaterial opticalMaterial(const MaterialFile& material) {
  const MaterialLayer& l = material.layers.front();
  optics::ScatteringMaterial m;
  m.name = material.name;
  m.g = l.g;
  m.eta = material.ior;
  const float s[3] = {l.sigmaS.x, l.sigmaS.y, l.sigmaS.z}, t[3] = {l.sigmaT.x, l.sigmaT.y, l.sigmaT.z};
  for (int c = 0; c < optics::kChannels; ++c) {
    m.sigmaS[std::size_t(c)] = s[c];
    m.sigmaA[std::size_t(c)] = double(t[c]) - double(s[c]);
  }
  m.source = l.source.empty() ? material.file.filename().string() : l.source;
  return m;
}

float firstLayerMinSigmaT(const MaterialFile& material) {
  const Float3 t = material.layers.front().sigmaT;
  return std::min({t.x, t.y, t.z});
}

Result<subsurface::LayerStack> layerStack(const MaterialFile& material, const Image8& subsurfaceMap) {
  subsurface::LayerStack stack;
  stack.depthScaleMm = material.depthScaleMm;
  for (const auto& l : material.layers)
    stack.layers.push_back({l.sigmaS, l.sigmaT, l.g});
  auto maps = subsurface::subsurfaceMapsFromImages(std::span<const Image8>(&subsurfaceMap, 1));
  if (!maps) return Error{"material file " + material.file.string() + ": " + maps.error().message};
  stack.maps = std::move(*maps);
  if (auto ok = subsurface::validateLayerStack(stack); !ok)
    return Error{"material file " + material.file.string() + ": " + ok.error().message};
  return stack;
}

}  // namespace tissue::scene
