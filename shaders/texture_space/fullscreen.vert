#version 330 core
// One triangle covering the viewport; v_texCoord spans [0, u_mapScale] over it, the part of the
// map the depth-based size uses (Jimenez §4: texture space limited to (0..s)).
uniform float u_mapScale;
out vec2 v_texCoord;

void main() {
  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));  // (0,0), (2,0), (0,2)
  v_texCoord = p * u_mapScale;
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
