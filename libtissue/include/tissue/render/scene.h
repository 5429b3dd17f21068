#pragma once
/// \file
/// What the renderer draws: camera, lights and objects as plain structs with defaults.
/// Lengths are mm in world space (the mesh's own coordinates); colours are linear RGB unless
/// a field says otherwise. Everything here may change every frame.

#include <cstdint>
#include <vector>

#include "tissue/core/types.h"
#include "tissue/render/shading.h"

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

/// Point lights sit at a position; directional lights shine along a direction from infinity.
enum class LightType { Point, Directional };

/// One light without distance falloff (a surgical lamp is far compared with the field).
struct Light {
  LightType type = LightType::Point;
  Float3 positionMm{150.0f, 200.0f, 250.0f};  ///< mm (point lights)
  Float3 direction{-0.4f, -0.6f, -0.7f};      ///< unitless, the way the light travels (directional)
  Float3 color{1.0f, 0.97f, 0.92f};           ///< linear RGB, unitless 0..1
  float intensity = 2.5f;                     ///< unitless radiance scale; radiance = color * intensity
  /// Render a shadow map for this light (one depth pass over every object) and filter it with
  /// PCF. A point light's map is one perspective frustum aimed at the objects' bounding sphere
  /// (a lamp outside the field), not a cube map.
  bool castsShadows = false;
  float shadowBiasMm = 0.3f;  ///< mm, depth bias against self-shadowing (scaled by the slope)
};

/// Blinn-Phong material parameters (the base colour comes from the texture).
struct Material {
  float specular = 0.04f;                 ///< unitless specular reflectance, 0..1 (moist tissue ~0.02-0.05)
  float shininess = 64.0f;                ///< Blinn-Phong exponent, unitless
  Float3 ambient{0.06f, 0.055f, 0.055f};  ///< linear RGB ambient radiance
};

/// A mesh uploaded to a renderer (Renderer::createMesh); 0 = none.
struct MeshHandle {
  std::uint32_t id = 0;
  explicit operator bool() const { return id != 0; }
};

/// One object of the scene: mesh, textures, material and shading method.
struct SceneObject {
  MeshHandle mesh;
  TextureHandle baseColor;  ///< sRGB base colour; none: a tissue-like constant
  TextureHandle normalMap;  ///< tangent-space normal map; none: the vertex normals shade
  Material material;
  MethodSettings method;  ///< the shading method and its settings (default: Lit)
  bool visible = true;
};

/// Everything besides the uploaded meshes and textures that one frame needs.
struct Scene {
  Camera camera;
  std::vector<Light> lights{Light{}};  ///< at most kMaxLights
  /// The objects to draw. When empty, the mesh and textures given to Renderer::setMesh,
  /// setBaseColor and setNormalMap are drawn Lit with `material` (the single-mesh API).
  std::vector<SceneObject> objects;
  Material material;                       ///< the single-mesh API's material
  Float3 background{0.05f, 0.05f, 0.06f};  ///< clear colour, sRGB-encoded 0..1 (written as is)
  float exposure = 1.0f;                   ///< unitless, multiplies radiance before the tone map
};

/// The most lights a scene may have.
inline constexpr int kMaxLights = 4;

/// A camera looking along `direction` (unitless, from eye to target) at the centre of the box
/// [lo, hi] (mm), far enough that the box's bounding sphere fills the smaller field of view
/// for an image of `aspect` = width / height, with near/far planes around the sphere.
Camera frameBoundingBox(Float3 lo, Float3 hi, float aspect, Float3 direction = {-0.3f, -0.35f, -1.0f});

}  // namespace tissue::render
