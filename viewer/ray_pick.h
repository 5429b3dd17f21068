#pragma once
/// \file
/// Picking the tissue under the cursor: a ray from the cursor through the camera, the
/// ray-triangle test of Möller & Trumbore ("Fast, Minimum Storage Ray/Triangle Intersection",
/// JGT 1997), and the nearest hit over a whole mesh by brute force (the liver's 27k triangles
/// take well under a millisecond, and a pick happens once per button press).

#include <cstdint>
#include <optional>
#include <span>

#include "tissue/core/types.h"
#include "tissue/render/scene.h"

namespace tissue::viewer {

/// A half-line: origin + t * direction, t >= 0.
struct Ray {
  Float3 origin;     ///< mm, world space
  Float3 direction;  ///< unit
};

/// Where a ray meets a mesh.
struct RayHit {
  std::uint32_t triangle = 0;  ///< index into the triangle array
  float distanceMm = 0.0f;     ///< mm along the ray (t, the direction being unit)
  Float3 pointMm;              ///< mm, origin + t * direction
};

/// The ray from `camera`'s eye through the cursor at (`cursorX`, `cursorY`) pixels from the
/// top-left corner of a `width` x `height` pixel window (the camera's aspect is width / height).
Ray rayFromCursor(const render::Camera& camera, double cursorX, double cursorY, int width, int height);

/// Where `point` (mm) appears in a `width` x `height` window, pixels from the top-left
/// corner; empty when it lies behind the eye. The inverse of rayFromCursor.
std::optional<Float2> projectToCursor(const render::Camera& camera, Float3 point, int width, int height);

/// Möller-Trumbore: the distance t (mm) along `ray` at which it crosses triangle (a, b, c)
/// (mm), either side facing; empty on a miss, a hit behind the origin or a ray parallel to the
/// triangle's plane.
std::optional<float> intersectTriangle(const Ray& ray, Float3 a, Float3 b, Float3 c);

/// The hit nearest to the ray's origin over `triangles` (indices into `positions`, mm).
std::optional<RayHit> nearestHit(const Ray& ray, std::span<const Float3> positions,
                                 std::span<const Triangle> triangles);

}  // namespace tissue::viewer
