// The renderer's frame as the path-traced truth's inputs (truth_view.h).
#include "tissue/scene/truth_view.h"

#include "tissue/scene/truth_material.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace tissue::scene {
namespace {

std::string where(const OrganAssets& organ) {
  return organ.material.file.empty() ? std::string("the default material")
                                     : "material file " + organ.material.file.string();
}

// One layer's coefficients: finite, sigma_s >= 0, sigma_t >= sigma_s per channel.
Result<void> checkLayer(const OrganAssets& organ, std::size_t i) {
  const MaterialLayer& l = organ.material.layers[i];
  const float s[3] = {l.sigmaS.x, l.sigmaS.y, l.sigmaS.z}, t[3] = {l.sigmaT.x, l.sigmaT.y, l.sigmaT.z};
  for (int c = 0; c < 3; ++c) {
    if (!std::isfinite(s[c]) || s[c] < 0.0f)
      return Error{where(organ) + ": layers[" + std::to_string(i) +
                   "].sigma_s has no finite value >= 0 for channel " + std::to_string(c) +
                   "; give sigma_s in mm^-1 for red, green and blue"};
    if (!std::isfinite(t[c]) || t[c] < s[c])
      return Error{where(organ) + ": layers[" + std::to_string(i) + "].sigma_t (channel " +
                   std::to_string(c) +
                   ") is missing or below sigma_s; give sigma_t = sigma_a + sigma_s in mm^-1"};
  }
  return {};
}

}  // namespace

Result<truth::TruthMaterial> truthMaterialOf(const OrganAssets& organ) {
  const MaterialFile& file = organ.material;
  if (file.layers.empty())
    return Error{where(organ) + ": layers is empty; give at least one layer (top first)"};
  std::size_t used = 1;  // layers the transport sees: the first alone without a subsurface map
  if (organ.subsurfaceMap) {
    auto stack = layerStack(file, *organ.subsurfaceMap);
    if (!stack) return stack.error();
    used = std::size_t(stack->maps.mapCount) * 4 + 1;
    if (file.layers.size() != used)
      return Error{where(organ) + ": layers has " + std::to_string(file.layers.size()) +
                   " entries but its subsurface map bounds " + std::to_string(used) +
                   "; give one layer per boundary and one below"};
    // A layer depth outside the mesh: the deepest boundary must lie well inside the organ.
    float deepest = 0.0f;
    for (float v : stack->maps.depths)
      deepest = std::max(deepest, v);
    const Float3 size = organ.bounds.hi - organ.bounds.lo;
    const float limit = 0.5f * std::min({size.x, size.y, size.z});
    if (deepest * stack->depthScaleMm > limit)
      return Error{where(organ) + ": depth_scale_mm = " + std::to_string(stack->depthScaleMm) +
                   " puts the deepest layer boundary " + std::to_string(deepest * stack->depthScaleMm) +
                   " mm below the surface, outside the mesh (half its smallest extent is " +
                   std::to_string(limit) + " mm); lower depth_scale_mm"};
  }
  for (std::size_t i = 0; i < used; ++i)
    if (auto ok = checkLayer(organ, i); !ok) return ok.error();
  // The conversion itself is the material reader's (truth_material.h), so the truth and the
  // renderer's methods read one file one way; without a map the top layer alone, unbounded.
  if (organ.subsurfaceMap) return truthMaterial(file, *organ.subsurfaceMap);
  MaterialFile top = file;
  top.layers.resize(1);
  return truthMaterial(top, std::span<const double>{});
}

truth::TruthCamera truthCameraOf(const render::Camera& camera) {
  truth::TruthCamera c;
  c.projection = truth::Projection::Pinhole;
  c.eye = camera.eye;
  c.target = camera.target;
  c.up = camera.up;
  c.verticalFovDeg = camera.verticalFovDeg;
  return c;
}

std::vector<truth::TruthLight> truthLightsOf(std::span<const render::Light> lights) {
  std::vector<truth::TruthLight> out;
  for (const render::Light& l : lights) {
    truth::TruthLight t;
    t.type = l.type == render::LightType::Directional ? truth::TruthLightType::Directional
                                                      : truth::TruthLightType::Point;
    t.positionMm = l.positionMm;
    t.direction = l.direction;
    t.radiance = l.color * l.intensity;
    t.castsShadows = true;
    out.push_back(t);
  }
  return out;
}

double roughnessOf(const render::Material& material) {
  return std::sqrt(2.0 / (double(std::max(0.0f, material.shininess)) + 2.0));
}

Result<truth::TruthImage> renderTruth(const OrganAssets& organ, std::span<const Float3> positionsMm,
                                      const render::Scene& frame, const truth::PathTraceSettings& settings) {
  if (positionsMm.size() != organ.mesh.positions.size())
    return Error{"truth view: " + std::to_string(positionsMm.size()) + " positions for " +
                 std::to_string(organ.mesh.positions.size()) +
                 " render vertices; give one per render vertex"};
  auto material = truthMaterialOf(organ);
  if (!material) return material.error();
  const std::vector<truth::TruthLight> lights = truthLightsOf(frame.lights);
  truth::PathTraceSettings s = settings;
  s.surfaceRoughness = roughnessOf(frame.material);
  const truth::TruthMesh mesh{positionsMm, organ.mesh.triangles, organ.mesh.uvs};
  return truth::renderPathTraced(mesh, *material, lights, truthCameraOf(frame.camera), s);
}

Result<truth::TruthImage> renderTruth(Scene& scene, OrganId organ, const truth::PathTraceSettings& settings,
                                      const Mat4& model) {
  if (organ >= scene.organCount())
    return Error{"truth view: organ " + std::to_string(organ) + ": no such organ (the scene has " +
                 std::to_string(scene.organCount()) + ")"};
  const OrganAssets& assets = scene.assets(organ);
  std::vector<Float3> positions = assets.mesh.positions;
  if (const OrganLoop* loop = scene.loop(organ)) {
    const std::span<const Float3> geometric = loop->geometricPositions();
    for (std::size_t i = 0; i < positions.size(); ++i)
      positions[i] = geometric[assets.mesh.geometricIndex[i]];
  }
  for (Float3& p : positions)
    p = transformPoint(model, p);
  render::Scene frame = scene.renderScene();
  frame.camera = scene.camera();
  return renderTruth(assets, positions, frame, settings);
}

}  // namespace tissue::scene
