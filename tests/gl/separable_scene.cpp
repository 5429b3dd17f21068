#include "separable_scene.h"

#include <cmath>
#include <utility>

#include "test_scene.h"

namespace tissue::test {

std::vector<Float4> gaussianTaps(float sigmaMm, int taps) {
  std::vector<Float4> kernel;
  float sum = 0.0f;
  for (int i = 0; i < taps; ++i) {
    const float x =
        taps == 1 ? 0.0f : (-3.0f + 6.0f * static_cast<float>(i) / static_cast<float>(taps - 1)) * sigmaMm;
    const float w = taps == 1 ? 1.0f : std::exp(-x * x / (2.0f * sigmaMm * sigmaMm));
    kernel.push_back({w, w, w, x});
    sum += w;
  }
  for (Float4& k : kernel)
    k = {k.x / sum, k.y / sum, k.z / sum, k.w};
  return kernel;
}

reference::RadialProfile gaussianProfile(float sigmaMm) {
  reference::RadialProfile p;
  for (int i = 0; i <= 1000; ++i) {
    const float r = 4.0f * sigmaMm * static_cast<float>(i) / 1000.0f;
    const float v = std::exp(-r * r / (2.0f * sigmaMm * sigmaMm)) / (2.0f * 3.14159265f * sigmaMm * sigmaMm);
    p.radiusMm.push_back(r);
    p.value.push_back({v, v, v});
  }
  return p;
}

render::Scene frontScene() {
  render::Scene scene;
  scene.camera.eye = {0.0f, 0.0f, 200.0f};
  scene.camera.nearMm = 50.0f;
  scene.camera.farMm = 400.0f;
  scene.lights[0].type = render::LightType::Directional;
  scene.lights[0].direction = {0.0f, 0.0f, -1.0f};
  return scene;
}

render::SceneObject separableObject(render::MeshHandle mesh, render::SeparableSettings settings) {
  render::SceneObject o;
  o.mesh = mesh;
  o.method = std::move(settings);
  return o;
}

Result<render::Scene> texturedPatchScene(render::Renderer& renderer, const Image8& texture,
                                         render::SeparableSettings settings) {
  auto mesh = renderer.createMesh(makePatch(200.0f, 4, 0.0f).arrays());
  if (!mesh) return mesh.error();
  auto base = renderer.createTexture(texture);
  if (!base) return base.error();
  render::Scene scene = frontScene();
  scene.objects = {separableObject(*mesh, std::move(settings))};
  scene.objects[0].baseColor = *base;
  return scene;
}

double meanOver(const render::FloatImage& image, int x0, int x1, int y0, int y1, int channel) {
  double sum = 0.0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      const Float4& p = image.at(x, y);
      sum += static_cast<double>(channel == 0 ? p.x : (channel == 1 ? p.y : p.z));
    }
  }
  return sum / ((x1 - x0) * (y1 - y0));
}

}  // namespace tissue::test
