#pragma once
/// \file
/// What the renderer draws with: camera, light and material as plain structs with defaults.
/// Lengths are mm in world space (the mesh's own coordinates); colours are linear RGB unless
/// a field says otherwise.

#include "tissue/core/types.h"

namespace tissue::render {

/// A perspective look-at camera.
struct Camera {
  Float3 eye{0.0f, 0.0f, 200.0f};   ///< mm
  Float3 target{0.0f, 0.0f, 0.0f};  ///< mm, the point looked at
  Float3 up{0.0f, 1.0f, 0.0f};      ///< unitless direction, not parallel to target - eye
  float verticalFovDeg = 40.0f;     ///< degrees, full vertical field of view
  float nearMm = 1.0f;              ///< mm, near clipping distance (> 0)
  float farMm = 2000.0f;            ///< mm, far clipping distance
};

/// One point light without distance falloff (a surgical lamp is far compared with the field).
struct PointLight {
  Float3 positionMm{150.0f, 200.0f, 250.0f};  ///< mm
  Float3 color{1.0f, 0.97f, 0.92f};           ///< linear RGB, unitless 0..1
  float intensity = 2.5f;                     ///< unitless radiance scale; radiance = color * intensity
};

/// Blinn-Phong material parameters (the base colour comes from the texture).
struct Material {
  float specular = 0.04f;                 ///< unitless specular reflectance, 0..1 (moist tissue ~0.02-0.05)
  float shininess = 64.0f;                ///< Blinn-Phong exponent, unitless
  Float3 ambient{0.06f, 0.055f, 0.055f};  ///< linear RGB ambient radiance
  float exposure = 1.0f;                  ///< unitless, multiplies radiance before the tone map
};

/// Everything besides the mesh and textures that one frame needs.
struct Scene {
  Camera camera;
  PointLight light;
  Material material;
  Float3 background{0.05f, 0.05f, 0.06f};  ///< clear colour, sRGB-encoded 0..1 (written as is)
};

/// A camera looking along `direction` (unitless, from eye to target) at the centre of the box
/// [lo, hi] (mm), far enough that the box's bounding sphere fills the smaller field of view
/// for an image of `aspect` = width / height, with near/far planes around the sphere.
Camera frameBoundingBox(Float3 lo, Float3 hi, float aspect, Float3 direction = {-0.3f, -0.35f, -1.0f});

}  // namespace tissue::render
