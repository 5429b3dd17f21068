// The one reader of data/materials/*.json (material_file.h). nlohmann-json stays in this file.
#include "tissue/scene/material_file.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "tissue/core/atomic_file.h"
#include "tissue/optics/dipole.h"
#include "tissue/optics/reflectance.h"

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

namespace {
Result<MaterialFile> readMaterialFileUnguarded(const std::filesystem::path& file,
                                               const MaterialFileOptions& options);
}  // namespace

Result<MaterialFile> readMaterialFile(const std::filesystem::path& file, const MaterialFileOptions& options) {
  // nlohmann's accessors throw on a value of the wrong type (value("name") of a number: found
  // by the material fuzz target); the library never throws across its API.
  try {
    return readMaterialFileUnguarded(file, options);
  } catch (const json::exception& e) {
    return Error{"material file " + file.string() + ": a value has the wrong type (" + e.what() +
                 "); see docs/DATA.md for the schema"};
  }
}

namespace {
Result<MaterialFile> readMaterialFileUnguarded(const std::filesystem::path& file,
                                               const MaterialFileOptions& options) {
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
  if (const auto detail = doc.find("base_color_detail"); detail != doc.end()) {
    if (!detail->is_boolean())
      return Error{where +
                   ": 'base_color_detail' must be true or false (the painted detail on the optical albedo)"};
    m.baseColorDetail = detail->get<bool>();
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
}  // namespace

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

LayerReflectance layerReflectance(const MaterialFile& material, std::size_t layer) {
  const MaterialLayer& l = material.layers.at(layer);
  const float s[3] = {l.sigmaS.x, l.sigmaS.y, l.sigmaS.z}, t[3] = {l.sigmaT.x, l.sigmaT.y, l.sigmaT.z};
  float single[3], multiple[3], tr[3];
  for (int c = 0; c < 3; ++c) {
    const double sigmaA = std::max(double(t[c]) - double(s[c]), 0.0);
    const auto r = optics::semiInfiniteReflectance(sigmaA, s[c], l.g, material.ior);
    single[c] = float(r.single);
    multiple[c] = float(r.multiple);
    tr[c] = float(optics::makeDipole(sigmaA, double(s[c]) * (1.0 - double(l.g)), material.ior).sigmaTr);
  }
  LayerReflectance out;
  out.single = {single[0], single[1], single[2]};
  out.multiple = {multiple[0], multiple[1], multiple[2]};
  out.total = {single[0] + multiple[0], single[1] + multiple[1], single[2] + multiple[2]};
  out.sigmaTr = {tr[0], tr[1], tr[2]};
  return out;
}

Float3 opticalAlbedo(const MaterialFile& material) {
  return layerReflectance(material, 0).total;
}

namespace {

float linearToSrgb(float v) {
  v = std::clamp(v, 0.0f, 1.0f);
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}
float srgbToLinear(float v) {
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

// Rec. 709 luminance of texel i of an sRGB image (linear).
float luminance(const Image8& image, std::size_t i) {
  const std::uint8_t* p = &image.pixels[i * std::size_t(image.channels)];
  if (image.channels < 3) return srgbToLinear(float(p[0]) / 255.0f);
  return 0.2126f * srgbToLinear(float(p[0]) / 255.0f) + 0.7152f * srgbToLinear(float(p[1]) / 255.0f) +
         0.0722f * srgbToLinear(float(p[2]) / 255.0f);
}

// The painted image's luminance over its mean, per texel (empty: no detail).
std::vector<float> detailOf(const Image8* painted) {
  std::vector<float> d;
  if (!painted || painted->width <= 0 || painted->height <= 0) return d;
  const std::size_t n = std::size_t(painted->width) * std::size_t(painted->height);
  d.resize(n);
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    d[i] = luminance(*painted, i);
    sum += double(d[i]);
  }
  const float mean = float(sum / double(n));
  for (float& v : d)
    v = mean > 0.0f ? v / mean : 1.0f;
  return d;
}

void putTexel(Image8& image, std::size_t i, Float3 linear) {
  std::uint8_t* p = &image.pixels[i * 4];
  p[0] = std::uint8_t(std::lround(255.0f * linearToSrgb(linear.x)));
  p[1] = std::uint8_t(std::lround(255.0f * linearToSrgb(linear.y)));
  p[2] = std::uint8_t(std::lround(255.0f * linearToSrgb(linear.z)));
  p[3] = 255;
}

Float3 scaled(Float3 v, float s) {
  return {v.x * s, v.y * s, v.z * s};
}

}  // namespace

Image8 opticalBaseColor(const MaterialFile& material, const Image8* painted) {
  const Float3 albedo = opticalAlbedo(material);
  const std::vector<float> detail = material.baseColorDetail ? detailOf(painted) : std::vector<float>{};
  Image8 out;
  out.width = detail.empty() ? 4 : painted->width;
  out.height = detail.empty() ? 4 : painted->height;
  out.channels = 4;
  out.pixels.assign(std::size_t(out.width) * std::size_t(out.height) * 4, 0);
  for (std::size_t i = 0; i < std::size_t(out.width) * std::size_t(out.height); ++i)
    putTexel(out, i, detail.empty() ? albedo : scaled(albedo, detail[i]));
  return out;
}

Image8 opticalLayerImage(const MaterialFile& material, const Image8& subsurfaceMap, float depthMm,
                         const Image8* painted) {
  std::vector<Float3> albedo;
  for (std::size_t l = 0; l < material.layers.size(); ++l)
    albedo.push_back(layerReflectance(material, l).total);
  const bool sameSize =
      painted && painted->width == subsurfaceMap.width && painted->height == subsurfaceMap.height;
  const std::vector<float> detail =
      material.baseColorDetail && sameSize ? detailOf(painted) : std::vector<float>{};
  Image8 out;
  out.width = subsurfaceMap.width;
  out.height = subsurfaceMap.height;
  out.channels = 4;
  out.pixels.assign(std::size_t(out.width) * std::size_t(out.height) * 4, 0);
  const int channels = std::min(subsurfaceMap.channels, 4);
  for (std::size_t i = 0; i < std::size_t(out.width) * std::size_t(out.height); ++i) {
    // Layer i ends at boundary i (François §2.1): the layer at depthMm is the count of
    // boundaries above it.
    std::size_t layer = 0;
    for (int b = 0; b < channels; ++b) {
      const float boundaryMm =
          material.depthScaleMm *
          float(subsurfaceMap.pixels[i * std::size_t(subsurfaceMap.channels) + std::size_t(b)]) / 255.0f;
      if (boundaryMm <= depthMm) layer = std::size_t(b) + 1;
    }
    layer = std::min(layer, albedo.size() - 1);
    putTexel(out, i, detail.empty() ? albedo[layer] : scaled(albedo[layer], detail[i]));
  }
  return out;
}

float specularF0(const MaterialFile& material) {
  const float r = (material.ior - 1.0f) / (material.ior + 1.0f);
  return r * r;
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
