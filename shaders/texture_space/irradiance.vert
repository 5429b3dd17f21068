#version 330 core
// Texture-space diffusion, irradiance pass (d'Eon et al. 2007): each triangle is rasterised at
// its texture coordinates, so the map holds the irradiance of the whole surface. Jimenez and
// Gutierrez 2008: §3 visibility per vertex (Listing 1), §5 clipping in eye space (Listing 4).

layout(location = 0) in vec3 a_position;  // mm, object space
layout(location = 1) in vec3 a_normal;    // unit, object space
layout(location = 2) in vec4 a_tangent;   // unit T, handedness w (normal mapping, irradiance_scene.frag)
layout(location = 3) in vec2 a_uv;

// The object's model matrix (u_model, u_normalMatrix): world position and frame as the camera
// pass (common/surface.vert) has them, so culling, clipping and lighting agree with it.
#include "common/model.glsl"

uniform mat4 u_view;             // world (mm) to eye (mm)
uniform vec4 u_clipPlanes[6];    // eye-space frustum planes, Jimenez eq. 6 (Pi_eye = P^T Pi_clip)
uniform int u_clip;              // 1: clip against them (§5)

out float gl_ClipDistance[6];
out vec3 v_worldPosition;
out vec3 v_normal;
out vec4 v_tangent;
out vec2 v_uv;
out float v_eyeDot;  // cos of the angle between the normal and the direction to the eye

void main() {
  vec3 world = modelPosition(a_position);
  vec3 normal = modelNormal(a_normal);
  vec4 eye = u_view * vec4(world, 1.0);
  vec3 normalEye = mat3(u_view) * normal;  // the view matrix is a rotation and translation
  // §3 Listing 1 uses the fixed view vector (0, 0, 1); the direction to the eye is the exact one
  // under perspective.
  v_eyeDot = dot(normalize(normalEye), normalize(-eye.xyz));
  v_worldPosition = world;
  v_normal = normal;
  v_tangent = modelTangent(a_tangent);
  v_uv = a_uv;
  for (int i = 0; i < 6; ++i)
    gl_ClipDistance[i] = u_clip == 1 ? dot(u_clipPlanes[i], eye) : 1.0;
  // The viewport is (0, 0, T, T) (§4): uv in [0, 1] fills it.
  gl_Position = vec4(a_uv * 2.0 - 1.0, 0.0, 1.0);
}
