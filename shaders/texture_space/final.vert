#version 330 core
// Texture-space diffusion, final pass: the mesh seen by the camera, looking up its diffused
// irradiance maps at its texture coordinates.
layout(location = 0) in vec3 a_position;  // mm
layout(location = 1) in vec3 a_normal;    // unit
layout(location = 3) in vec2 a_uv;

uniform mat4 u_viewProjection;  // world (mm) to clip
uniform float u_mapScale;       // s of Jimenez eq. 3
uniform vec3 u_offset;          // mm, translation of this instance

out vec3 v_worldPosition;
out vec3 v_normal;
out vec2 v_uv;       // the base colour's coordinates
out vec2 v_mapCoord; // the irradiance maps' coordinates, in [0, s]

void main() {
  v_worldPosition = a_position + u_offset;
  v_normal = a_normal;
  v_uv = a_uv;
  v_mapCoord = a_uv * u_mapScale;
  gl_Position = u_viewProjection * vec4(v_worldPosition, 1.0);
}
