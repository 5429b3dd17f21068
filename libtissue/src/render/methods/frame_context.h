#pragma once
// What a shading method sees of one frame: GL, the camera, the lights and shadow maps, the
// frame's targets, the pass timers, and its own objects with their GPU resources. Each method
// (one file here, shaders in shaders/<method>/) draws its objects into the geometry targets
// in its geometry pass and may add post passes; see docs/ARCHITECTURE.md, "Adding a method".
#include <array>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "../frame_targets.h"
#include "../lights.h"
#include "../mesh_buffers.h"
#include "../model_transform.h"
#include "../pass_timers.h"
#include "tissue/gl/objects.h"
#include "tissue/gl/shader_library.h"
#include "tissue/render/scene.h"

namespace tissue::render {

/// Texture units every surface shader uses.
enum TextureUnit : int { kUnitBaseColor = 0, kUnitNormalMap = 1, kUnitShadowMaps = 2, kUnitMethod0 = 3 };

/// The most textures a method's settings may name (parallax: opacity map and inner layers).
inline constexpr std::size_t kMaxMethodTextures = 4;

/// One object to draw, resolved to GPU names.
struct ObjectDraw {
  const SceneObject* object = nullptr;
  const MeshBuffers* mesh = nullptr;
  GLuint baseColor = 0;  ///< a default when the object has none
  GLuint normalMap = 0;  ///< 0: no normal mapping
  float objectId = 0;    ///< 1.. within the frame: the material ID of the geometry targets
  /// The textures the object's method settings name (methodTextureHandles in frame.cpp, same
  /// order), resolved; 0 where a handle is empty.
  std::array<GLuint, kMaxMethodTextures> methodTextures{};
  ModelTransform transform{};    ///< SceneObject::model with its normal matrix and scale
  glm::vec3 lo{0.0f}, hi{0.0f};  ///< world bounds, mm (the mesh's bounds through the model)
  /// The object's index in Scene::objects, as its passes are tagged (PassTiming::object).
  int index() const { return static_cast<int>(objectId) - 1; }
};

/// The frame as the methods see it.
struct FrameContext {
  const gl::GlApi& gl;
  const Scene& scene;
  int width = 0, height = 0;   ///< pixels
  glm::mat4 viewProjection{};  ///< world (mm) to clip
  glm::vec3 cameraForward{};   ///< unit
  const LightFrame& lights;
  GLuint shadowMaps = 0;  ///< GL_TEXTURE_2D_ARRAY of light distances (mm)
  FrameTargets& targets;
  PassTimers& passes;
  GLuint emptyVertexArray = 0;  ///< for full-screen triangles
  int objectCount = 0;          ///< every object of the frame (ids run 1..objectCount)
};

/// Binds the geometry targets and state for a geometry pass (depth test on, no blending).
void beginGeometryPass(const FrameContext& frame);

/// Sets the uniforms of common/surface.glsl and common/lights.glsl that are the same for every
/// object (camera, lights, shadow maps) on the program in use.
void setFrameUniforms(const FrameContext& frame, GLuint program);

/// Sets u_model and u_normalMatrix (common/surface.vert, texture_space/irradiance.vert) on the
/// program in use.
void setModelUniforms(const gl::GlApi& gl, GLuint program, const ModelTransform& transform);

/// Sets one object's uniforms (model, material, id) and textures, and draws it.
void drawSurface(const FrameContext& frame, GLuint program, const ObjectDraw& draw);

/// Surface programs in two variants: vertex normals, and normal-mapped (TISSUE_NORMAL_MAP).
struct SurfacePrograms {
  gl::Program flat, mapped;
  GLuint pick(const ObjectDraw& draw) const { return draw.normalMap ? mapped.id() : flat.id(); }
};

/// Builds common/surface.vert + `fragment` in both variants, with the samplers bound to units.
Result<SurfacePrograms> buildSurfacePrograms(const gl::GlApi& gl, const gl::ShaderLibrary& library,
                                             const char* fragment);

/// A full-screen triangle of `program` into whatever is bound.
void drawFullScreen(const FrameContext& frame);

}  // namespace tissue::render
