// Picking: ray from the cursor, Möller-Trumbore intersection, nearest hit.
#include "ray_pick.h"

#include <cmath>
#include <numbers>

#include "vec3_ops.h"

namespace tissue::viewer {
namespace {

/// The camera's orthonormal frame: forward (eye to target), right and up.
struct CameraFrame {
  Float3 forward, right, up;
  float tanHalfFov;  ///< tan of half the vertical field of view, unitless
};

CameraFrame cameraFrame(const render::Camera& camera) {
  CameraFrame f;
  f.forward = normalize(camera.target - camera.eye);
  f.right = normalize(cross(f.forward, camera.up));
  f.up = cross(f.right, f.forward);
  f.tanHalfFov = std::tan(camera.verticalFovDeg * std::numbers::pi_v<float> / 360.0f);
  return f;
}

}  // namespace

Ray rayFromCursor(const render::Camera& camera, double cursorX, double cursorY, int width, int height) {
  const CameraFrame f = cameraFrame(camera);
  const float aspect = float(width) / float(height > 0 ? height : 1);
  // Normalised device coordinates of the cursor: x right, y up, both -1..1 across the window.
  const float ndcX = float(2.0 * cursorX / width - 1.0);
  const float ndcY = float(1.0 - 2.0 * cursorY / height);
  const Float3 direction =
      f.forward + f.right * (ndcX * f.tanHalfFov * aspect) + f.up * (ndcY * f.tanHalfFov);
  return {camera.eye, normalize(direction)};
}

std::optional<Float2> projectToCursor(const render::Camera& camera, Float3 point, int width, int height) {
  const CameraFrame f = cameraFrame(camera);
  const float aspect = float(width) / float(height > 0 ? height : 1);
  const Float3 v = point - camera.eye;
  const float depth = dot(v, f.forward);  // mm in front of the eye
  if (depth <= 0.0f) return std::nullopt;
  const float ndcX = dot(v, f.right) / (depth * f.tanHalfFov * aspect);
  const float ndcY = dot(v, f.up) / (depth * f.tanHalfFov);
  return Float2{(ndcX + 1.0f) * 0.5f * float(width), (1.0f - ndcY) * 0.5f * float(height)};
}

std::optional<float> intersectTriangle(const Ray& ray, Float3 a, Float3 b, Float3 c) {
  // Möller-Trumbore: solve origin + t d = (1 - u - v) a + u b + v c by Cramer's rule.
  constexpr float kParallel = 1e-12f;  // |det| below this: the ray runs along the plane
  const Float3 e1 = b - a;
  const Float3 e2 = c - a;
  const Float3 p = cross(ray.direction, e2);
  const float det = dot(e1, p);
  if (std::abs(det) < kParallel) return std::nullopt;
  const float invDet = 1.0f / det;
  const Float3 s = ray.origin - a;
  const float u = dot(s, p) * invDet;
  if (u < 0.0f || u > 1.0f) return std::nullopt;
  const Float3 q = cross(s, e1);
  const float v = dot(ray.direction, q) * invDet;
  if (v < 0.0f || u + v > 1.0f) return std::nullopt;
  const float t = dot(e2, q) * invDet;
  if (t < 0.0f) return std::nullopt;
  return t;
}

std::optional<RayHit> nearestHit(const Ray& ray, std::span<const Float3> positions,
                                 std::span<const Triangle> triangles) {
  std::optional<RayHit> best;
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const Triangle& tri = triangles[i];
    const auto t = intersectTriangle(ray, positions[tri[0]], positions[tri[1]], positions[tri[2]]);
    if (t && (!best || *t < best->distanceMm)) best = RayHit{std::uint32_t(i), *t, {}};
  }
  if (best) best->pointMm = ray.origin + ray.direction * best->distanceMm;
  return best;
}

}  // namespace tissue::viewer
