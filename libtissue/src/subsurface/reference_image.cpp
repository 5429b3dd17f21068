// CPU images of ray-marched single scattering (plane mode = the shader's model; mesh mode = reference).
#include "tissue/subsurface/reference_image.h"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <thread>

namespace tissue::subsurface {
namespace {

glm::dvec3 d3(Float3 v) {
  return {v.x, v.y, v.z};
}
Float3 f3(const glm::dvec3& v) {
  return {float(v.x), float(v.y), float(v.z)};
}

// The attributes at a camera-ray hit, interpolated with the hit's barycentrics (exact
// perspective-correct interpolation, as the rasteriser's).
ShadingPoint shadingPointAt(const MeshView& mesh, const RayHit& hit, const glm::dvec3& P,
                            const glm::dvec3& dir) {
  const Triangle& tri = mesh.triangles[hit.triangle];
  const double w[3] = {1.0 - hit.b1 - hit.b2, hit.b1, hit.b2};
  glm::dvec3 n(0.0), t(0.0), ns(0.0);
  double d = 0.0, handed = 0.0, u = 0.0, v = 0.0;
  for (int k = 0; k < 3; ++k) {
    const std::uint32_t i = tri[k];
    n += w[k] * d3(mesh.normals[i]);
    const Float4 tg = mesh.tangents[i], pl = mesh.planes[i];
    t += w[k] * glm::dvec3(tg.x, tg.y, tg.z);
    handed += w[k] * double(tg.w);
    ns += w[k] * glm::dvec3(pl.x, pl.y, pl.z);
    d += w[k] * double(pl.w);
    u += w[k] * double(mesh.uvs[i].x);
    v += w[k] * double(mesh.uvs[i].y);
  }
  n = glm::normalize(n);
  // Gram-Schmidt, as shaders/raymarch/march.glsl; a degenerate frame (a UV pole) does not drift.
  t -= glm::dot(t, n) * n;
  t = glm::length(t) < 1e-6 ? glm::dvec3(0.0) : glm::normalize(t);
  const glm::dvec3 b = (handed < 0.0 ? -1.0 : 1.0) * glm::cross(n, t);
  ShadingPoint p;
  p.position = f3(P);
  p.toEye = f3(-dir);
  p.normal = f3(n);
  p.plane = {float(ns.x), float(ns.y), float(ns.z), float(d)};
  p.tangent = f3(t);
  p.bitangent = f3(b);
  p.uv = {float(u), float(v)};
  p.uvPerMm = mesh.uvPerMm;
  return p;
}

}  // namespace

RadianceImage renderSingleScatteringCpu(const MeshView& mesh, const LayerStack& stack,
                                        std::span<const Light> lights, const PinholeCamera& camera,
                                        const CpuImageSettings& settings) {
  RadianceImage image;
  image.width = settings.width;
  image.height = settings.height;
  const std::size_t count = std::size_t(image.width) * image.height;
  image.radiance.assign(count, Float3{});
  image.covered.assign(count, 0);
  image.samples.assign(count, 0);
  image.viewCos.assign(count, 0.0f);
  const TriangleBvh bvh(mesh.positions, mesh.triangles);
  // Camera basis of glm::lookAt + glm::perspective; rays through pixel centres.
  const glm::dvec3 eye = d3(camera.eye);
  const glm::dvec3 forward = glm::normalize(d3(camera.target) - eye);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, d3(camera.up)));
  const glm::dvec3 up = glm::cross(right, forward);
  const double tanHalf = std::tan(glm::radians(double(camera.verticalFovDeg)) * 0.5);
  const double aspect = double(image.width) / image.height;
  const double pixelAngle = 2.0 * tanHalf / image.height;  // radians per pixel near the axis

  auto renderRows = [&](int rowBegin, int rowEnd) {
    for (int y = rowBegin; y < rowEnd; ++y)
      for (int x = 0; x < image.width; ++x) {
        const double sx = (2.0 * (x + 0.5) / image.width - 1.0) * tanHalf * aspect;
        const double sy = (1.0 - 2.0 * (y + 0.5) / image.height) * tanHalf;
        const glm::dvec3 dir = glm::normalize(forward + sx * right + sy * up);
        const auto hit = bvh.intersect({eye.x, eye.y, eye.z}, {dir.x, dir.y, dir.z}, 1e-6, 1e9);
        if (!hit) continue;
        const ShadingPoint p = shadingPointAt(mesh, *hit, eye + hit->t * dir, dir);
        MarchSettings march = settings.march;
        if (settings.adaptive) {
          const double cosView = std::max(double(glm::dot(d3(p.normal), -dir)), 0.1);
          const float pixelMm = float(hit->t * pixelAngle / cosView);
          const AdaptiveChoice choice = adaptiveMarch(p, stack, march, settings.adaptiveSettings, pixelMm);
          march.samples = choice.samples;
          march.maxLengthMm = choice.lengthMm;
        }
        const float jitter = settings.jitter ? pixelJitter(unsigned(x), unsigned(y), settings.seed) : 0.5f;
        const MarchResult r = marchSingleScattering(p, stack, lights, march, jitter,
                                                    settings.entry == EntryMode::Mesh ? &bvh : nullptr);
        const std::size_t i = std::size_t(y) * image.width + x;
        image.radiance[i] = r.radiance;
        image.covered[i] = 1;
        image.samples[i] = r.samplesUsed;
        image.viewCos[i] = float(-glm::dot(d3(p.normal), dir));
      }
  };
  const int threads = std::max(1, std::min(settings.threads, image.height));
  std::vector<std::thread> workers;
  // Interleave rows in blocks so threads get similar work.
  for (int w = 0; w < threads; ++w)
    workers.emplace_back([&, w] {
      for (int y = w * 4; y < image.height; y += threads * 4)
        renderRows(y, std::min(y + 4, image.height));
    });
  for (std::thread& t : workers)
    t.join();
  return image;
}

float uvPerMmOf(std::span<const Float3> positions, std::span<const Float2> uvs,
                std::span<const Triangle> triangles) {
  double area = 0.0, uvArea = 0.0;
  for (const Triangle& t : triangles) {
    const glm::dvec3 a = d3(positions[t[0]]), b = d3(positions[t[1]]), c = d3(positions[t[2]]);
    area += 0.5 * glm::length(glm::cross(b - a, c - a));
    const Float2 p = uvs[t[0]], q = uvs[t[1]], r = uvs[t[2]];
    uvArea += 0.5 * std::abs(double(q.x - p.x) * double(r.y - p.y) - double(q.y - p.y) * double(r.x - p.x));
  }
  return area > 0.0 ? float(std::sqrt(uvArea / area)) : 0.0f;
}

Image8 toDisplay(const RadianceImage& image, float exposure, Float3 background) {
  Image8 out(image.width, image.height, 4);
  auto encode = [](double c) {
    c = std::clamp(c, 0.0, 1.0);
    const double s = c < 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
    return std::uint8_t(std::lround(s * 255.0));
  };
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::size_t i = std::size_t(y) * image.width + x;
      std::uint8_t* px = out.at(x, y);
      if (image.covered[i]) {
        const double rgb[3] = {image.radiance[i].x, image.radiance[i].y, image.radiance[i].z};
        for (int c = 0; c < 3; ++c)
          px[c] = encode(double(exposure) * rgb[c] / (1.0 + double(exposure) * rgb[c]));
      } else {
        px[0] = std::uint8_t(std::lround(double(background.x) * 255.0));
        px[1] = std::uint8_t(std::lround(double(background.y) * 255.0));
        px[2] = std::uint8_t(std::lround(double(background.z) * 255.0));
      }
      px[3] = 255;
    }
  return out;
}

double displayRms(const Image8& a, const Image8& b, std::span<const std::uint8_t> mask) {
  if (a.width != b.width || a.height != b.height) return -1.0;
  double sum = 0.0;
  std::size_t n = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const std::size_t i = std::size_t(y) * a.width + x;
      if (!mask.empty() && !mask[i]) continue;
      for (int c = 0; c < 3; ++c) {
        const double d = (a.at(x, y)[c] - b.at(x, y)[c]) / 255.0;
        sum += d * d;
        ++n;
      }
    }
  return n > 0 ? std::sqrt(sum / double(n)) : 0.0;
}

double relativeRadianceRms(std::span<const Float3> a, std::span<const Float3> reference,
                           std::span<const std::uint8_t> mask) {
  if (a.size() != reference.size() || (!mask.empty() && mask.size() != a.size())) return -1.0;
  double diff = 0.0, norm = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!mask.empty() && !mask[i]) continue;
    const glm::dvec3 r = d3(reference[i]), d = d3(a[i]) - r;
    diff += glm::dot(d, d);
    norm += glm::dot(r, r);
  }
  return norm > 0.0 ? std::sqrt(diff / norm) : -1.0;
}

}  // namespace tissue::subsurface
