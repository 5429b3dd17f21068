#version 330 core
// Ray-marched subsurface texture mapping, vertex stage: passes the surface attributes and the
// per-vertex fitted plane (N_S, d) of François et al. 2006 eq. 14 to be interpolated (eq. 9).

layout(location = 0) in vec3 a_position;  // mm, world space
layout(location = 1) in vec3 a_normal;    // unit
layout(location = 2) in vec4 a_tangent;   // unit T, handedness w = +-1
layout(location = 3) in vec2 a_uv;
layout(location = 4) in vec4 a_plane;     // fitted plane: unit N_S, offset d (mm) along N_V

uniform mat4 u_viewProjection;  // world (mm) to clip space

out vec3 v_worldPosition;
out vec3 v_normal;
out vec4 v_tangent;
out vec2 v_uv;
out vec4 v_plane;

void main() {
  v_worldPosition = a_position;
  v_normal = a_normal;
  v_tangent = a_tangent;
  v_uv = a_uv;
  v_plane = a_plane;
  gl_Position = u_viewProjection * vec4(a_position, 1.0);
}
