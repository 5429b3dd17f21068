// The truth's material from a material file (truth_material.h).
#include "tissue/scene/truth_material.h"

#include <string>

namespace tissue::scene {
namespace {

truth::TruthMaterial layersOf(const MaterialFile& material) {
  truth::TruthMaterial t;
  for (const MaterialLayer& l : material.layers) {
    truth::TruthLayer layer;
    const float s[3] = {l.sigmaS.x, l.sigmaS.y, l.sigmaS.z}, e[3] = {l.sigmaT.x, l.sigmaT.y, l.sigmaT.z};
    truth::Rgb a{}, sc{};
    for (int c = 0; c < truth::kBands; ++c) {
      sc[std::size_t(c)] = double(s[c]);
      a[std::size_t(c)] = double(e[c]) - double(s[c]);
    }
    layer.sigmaA = a;
    layer.sigmaS = sc;
    layer.g = {double(l.g), double(l.g), double(l.g)};
    layer.n = double(material.ior);
    layer.name = l.name;
    t.layers.push_back(layer);
  }
  t.depthScaleMm = material.depthScaleMm;
  return t;
}

Result<truth::TruthMaterial> checked(truth::TruthMaterial t, const MaterialFile& material) {
  if (auto ok = truth::validateMaterial(t); !ok)
    return Error{"material file " + material.file.string() + ": " + ok.error().message};
  return t;
}

}  // namespace

Result<truth::TruthMaterial> truthMaterial(const MaterialFile& material, const Image8& subsurfaceMap) {
  auto stack = layerStack(material, subsurfaceMap);  // the renderer's own check of the map
  if (!stack) return stack.error();
  truth::TruthMaterial t = layersOf(material);
  t.maps = std::move(stack->maps);
  return checked(std::move(t), material);
}

Result<truth::TruthMaterial> truthMaterial(const MaterialFile& material,
                                           std::span<const double> thicknessMm) {
  if (thicknessMm.size() + 1 != material.layers.size())
    return Error{"material file " + material.file.string() + ": " + std::to_string(material.layers.size()) +
                 " layers need " + std::to_string(material.layers.size() - 1) + " thicknesses (mm), got " +
                 std::to_string(thicknessMm.size())};
  truth::TruthMaterial t = layersOf(material);
  for (std::size_t i = 0; i < thicknessMm.size(); ++i)
    t.layers[i].thicknessMm = thicknessMm[i];
  return checked(std::move(t), material);
}

}  // namespace tissue::scene
