#pragma once
/// \file
/// What the renderer draws: camera, lights and objects as plain structs with defaults.
/// Lengths are mm in world space (a mesh's own coordinates taken through its object's model
/// matrix); colours are linear RGB unless a field says otherwise. Everything here may change
/// every frame.

#include <array>
#include <cstdint>
#include <vector>

#include "tissue/core/types.h"
#include "tissue/render/handles.h"
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

/// The identity model matrix (column-major): object space is world space.
inline constexpr std::array<float, 16> kIdentityModel{1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f,
                                                      0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f};

/// One object of the scene: mesh, textures, material, shading method and model transform.
///
/// **The model matrix.** `model` takes the mesh's object space (mm) to world space (mm):
/// positions by M, normals and the local planes' normals N_S by the normal matrix
/// (M3^-1)^T (M3 the upper 3x3, computed once per object and frame on the CPU), tangents by M3
/// (they are surface vectors: M3 T stays tangent to the transformed surface, which the normal
/// matrix would not keep under non-uniform scale), the planes' offsets d so that the plane
/// maps onto its image (d' = d (N_S' . M3 N_p) / (N_S' . N_p'), = s d for a uniform scale s).
/// Every method honours it: lit, separable, texture-space (irradiance pass, culling, clipping
/// and map sizing from the world bounds and the eye), ray march, parallax (lightmap and
/// geometry) and the shadow passes (fitted to the transformed bounds).
/// - Supported: any affine M with det(M3) > 0 (rotation, translation, uniform and non-uniform
///   scale, shear). An object renders exactly as its mesh pre-transformed by M would (within
///   float rounding): the rule for every mm-valued setting follows from it.
/// - mm-valued settings are **world** mm and are not scaled with the object: separable kernel
///   offsets, texture-space variances, transmittance thicknesses, ray-march depths and layer
///   coefficients (mm^-1), parallax depths, shadow biases. Scaling an organ by s makes a
///   larger organ of the same tissue, not a magnified one. Under non-uniform scale the
///   scattering stays isotropic in world mm. Settings that describe the mesh's own UV layout
///   in mm (RayMarchSettings::uvPerMm, TextureSpaceSettings::texelsPerMm when given) must be
///   world values too (divide an object-space value by the scale); texelsPerMm = 0, measured
///   from the mesh at upload, is divided by the geometric-mean scale cbrt(det M3) (exact for
///   a uniform scale, an approximation under non-uniform scale).
/// - Refused (an Error from the render call): a non-finite M, a last row other than
///   (0, 0, 0, 1) (projective), det(M3) <= 0 (singular, or mirrored: mirroring would flip the
///   winding and the tangent handedness).
/// - It supersedes the texture-space irradiance pass's former instance offset (u_offset), which
///   is gone: an instance is an object with its own model matrix.
struct SceneObject {
  MeshHandle mesh;
  TextureHandle baseColor;  ///< sRGB base colour; none: a tissue-like constant
  TextureHandle normalMap;  ///< tangent-space normal map; none: the vertex normals shade
  Material material;
  MethodSettings method;  ///< the shading method and its settings (default: Lit)
  bool visible = true;
  /// Object space -> world space, mm, column-major (OpenGL's layout: model[col * 4 + row], the
  /// translation in model[12..14]); default identity. See above for what is supported.
  std::array<float, 16> model = kIdentityModel;
  /// Draw both faces (no back-face culling for this object; the back faces shade with the normal
  /// negated). For open surfaces (a patch, a cut organ), which would otherwise vanish when seen
  /// from behind. Closed meshes leave it off: culling halves their fragment work.
  bool doubleSided = false;
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
