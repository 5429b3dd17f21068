#include "test_scene.h"

#include <cmath>
#include <numbers>

namespace tissue::test {
namespace {
constexpr float kPi = std::numbers::pi_v<float>;

std::uint8_t toByte(float x) {
  return static_cast<std::uint8_t>(std::lround(std::fmin(std::fmax(x, 0.0f), 1.0f) * 255.0f));
}

Image8 normalMapFromHeight(int size, float strength, float (*height)(float, float)) {
  Image8 image(size, size, 3);
  const float h = 1.0f / static_cast<float>(size);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      // Image row 0 is the top, v = 1 (OBJ convention).
      const float u = (static_cast<float>(x) + 0.5f) * h;
      const float v = 1.0f - (static_cast<float>(y) + 0.5f) * h;
      const float du = (height(u + h, v) - height(u - h, v)) / (2.0f * h);
      const float dv = (height(u, v + h) - height(u, v - h)) / (2.0f * h);
      float n[3] = {-strength * du, -strength * dv, 1.0f};
      const float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      std::uint8_t* p = image.at(x, y);
      for (int c = 0; c < 3; ++c)
        p[c] = toByte(n[c] / len * 0.5f + 0.5f);
    }
  }
  return image;
}

}  // namespace

SphereMesh makeSphere(float radiusMm, int rings, int segments) {
  SphereMesh m;
  for (int i = 0; i <= rings; ++i) {
    const float v = static_cast<float>(i) / static_cast<float>(rings);
    const float theta = kPi * (1.0f - v);  // polar angle from +y: v = 0 at the south pole
    for (int j = 0; j <= segments; ++j) {
      const float u = static_cast<float>(j) / static_cast<float>(segments);
      const float phi = 2.0f * kPi * u;
      const Float3 n{std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi)};
      m.positions.push_back({radiusMm * n.x, radiusMm * n.y, radiusMm * n.z});
      m.normals.push_back(n);
      // T = dP/du normalised = (-sin phi, 0, -cos phi); dP/dv points north. B = w cross(N, T):
      // cross(N, T) at the equator, phi = 0: N = (1,0,0), T = (0,0,-1) -> (0, 1, 0) = north, w = +1.
      m.tangents.push_back({-std::sin(phi), 0.0f, -std::cos(phi), 1.0f});
      m.uvs.push_back({u, v});
    }
  }
  const auto index = [&](int i, int j) { return static_cast<std::uint32_t>(i * (segments + 1) + j); };
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < segments; ++j) {
      // Counter-clockwise seen from outside: (i, j) -> (i, j+1) -> (i+1, j+1) goes east then north.
      if (i > 0) m.triangles.push_back({index(i, j), index(i, j + 1), index(i + 1, j + 1)});
      if (i < rings - 1) m.triangles.push_back({index(i, j), index(i + 1, j + 1), index(i + 1, j)});
    }
  }
  return m;
}

SphereMesh makePatch(float sizeMm, int cells, float zMm) {
  SphereMesh m;
  for (int i = 0; i <= cells; ++i) {
    for (int j = 0; j <= cells; ++j) {
      const float u = static_cast<float>(j) / static_cast<float>(cells);
      const float v = static_cast<float>(i) / static_cast<float>(cells);
      m.positions.push_back({(u - 0.5f) * sizeMm, (v - 0.5f) * sizeMm, zMm});
      m.normals.push_back({0.0f, 0.0f, 1.0f});
      m.tangents.push_back({1.0f, 0.0f, 0.0f, 1.0f});
      m.uvs.push_back({u, v});
    }
  }
  const auto index = [&](int i, int j) { return static_cast<std::uint32_t>(i * (cells + 1) + j); };
  for (int i = 0; i < cells; ++i) {
    for (int j = 0; j < cells; ++j) {
      m.triangles.push_back({index(i, j), index(i, j + 1), index(i + 1, j + 1)});
      m.triangles.push_back({index(i, j), index(i + 1, j + 1), index(i + 1, j)});
    }
  }
  return m;
}

SphereMesh makeInsetPatch(int n, float sx, float sy, float stretchX) {
  SphereMesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const float u = float(i) / float(n), v = float(j) / float(n);
      m.positions.push_back({(u - 0.5f) * sx * stretchX, (v - 0.5f) * sy, 0.0f});
      m.normals.push_back({0.0f, 0.0f, 1.0f});
      m.tangents.push_back({1.0f, 0.0f, 0.0f, 1.0f});
      m.uvs.push_back({0.02f + 0.96f * u, 0.02f + 0.96f * v});
    }
  const auto id = [n](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

Image8 makeBumpyNormalMap(int size) {
  return normalMapFromHeight(size, 0.008f, [](float u, float v) {
    return std::sin(2.0f * kPi * 8.0f * u) * std::sin(2.0f * kPi * 5.0f * v) +
           0.6f * std::sin(2.0f * kPi * 11.0f * v);
  });
}

Image8 makeFlatNormalMap(int size) {
  return normalMapFromHeight(size, 0.0f, [](float, float) { return 0.0f; });
}

Image8 makeBaseColor(int size) {
  Image8 image(size, size, 3);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const float u = static_cast<float>(x) / static_cast<float>(size);
      const float stripe = 0.5f + 0.5f * std::sin(2.0f * kPi * 3.0f * u);
      std::uint8_t* p = image.at(x, y);
      p[0] = toByte(0.78f + 0.1f * stripe);
      p[1] = toByte(0.42f + 0.08f * stripe);
      p[2] = toByte(0.40f);
    }
  }
  return image;
}

double meanRedOver(const render::FloatImage& image, int x0, int x1, int y0, int y1) {
  double sum = 0.0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      sum += static_cast<double>(image.at(x, y).x);
  return sum / ((x1 - x0) * (y1 - y0));
}

GoldenSphere uploadGoldenSphere(render::Renderer& renderer) {
  const SphereMesh sphere = makeSphere(40.0f, 48, 96);
  return {renderer.createMesh(sphere.arrays()), renderer.createTexture(makeBaseColor(256)),
          renderer.createTexture(makeBumpyNormalMap(256))};
}

std::vector<render::ProfileGaussian> deonSkinGaussians() {
  return {{0.0064f, {0.233f, 0.455f, 0.649f}}, {0.0484f, {0.100f, 0.336f, 0.344f}},
          {0.187f, {0.118f, 0.198f, 0.0f}},    {0.567f, {0.113f, 0.007f, 0.007f}},
          {1.99f, {0.358f, 0.004f, 0.0f}},     {7.41f, {0.078f, 0.0f, 0.0f}}};
}

render::TextureSpaceSettings skinTextureSpace(int mapSize, bool optimised) {
  render::TextureSpaceSettings s;
  s.gaussians = deonSkinGaussians();
  s.cull = s.clip = s.depthSize = optimised;
  s.mapSize = mapSize;
  return s;
}

render::Scene goldenScene() {
  render::Scene scene;
  scene.camera.eye = {0.0f, 25.0f, 130.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.camera.verticalFovDeg = 40.0f;
  scene.camera.nearMm = 10.0f;
  scene.camera.farMm = 400.0f;
  scene.lights[0].positionMm = {120.0f, 140.0f, 160.0f};
  scene.material.specular = 0.2f;
  scene.material.shininess = 40.0f;
  return scene;
}

}  // namespace tissue::test
