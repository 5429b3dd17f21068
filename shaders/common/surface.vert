#version 330 core
// Surface vertex stage shared by the shading methods. Attributes arrive in object space (mm)
// and go to world space through the object's model matrix (common/model.glsl; the identity
// when the mesh is already in world space, as the mesh module and the simulator give it).

layout(location = 0) in vec3 a_position;  // mm, object space
layout(location = 1) in vec3 a_normal;    // unit
layout(location = 2) in vec4 a_tangent;   // unit T, handedness w = +-1
layout(location = 3) in vec2 a_uv;
layout(location = 4) in vec4 a_plane;     // local plane (N_S, d mm), François eq. 14; optional

#include "common/model.glsl"

uniform mat4 u_viewProjection;  // world (mm) to clip space

out vec3 v_worldPosition;
out vec3 v_normal;
out vec4 v_tangent;
out vec2 v_uv;
out vec4 v_plane;

void main() {
  v_worldPosition = modelPosition(a_position);
  v_normal = modelNormal(a_normal);
  v_tangent = modelTangent(a_tangent);
  v_uv = a_uv;
  v_plane = modelPlane(a_plane, a_normal);
  gl_Position = u_viewProjection * vec4(v_worldPosition, 1.0);
}
