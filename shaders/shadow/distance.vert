#version 330 core
// Shadow pass, vertex stage: world (mm) to the light's clip space.
layout(location = 0) in vec3 a_position;  // mm
uniform mat4 u_shadowMatrix;              // world (mm) to the shadow map's clip space
out vec3 v_worldPosition;
void main() {
  v_worldPosition = a_position;
  gl_Position = u_shadowMatrix * vec4(a_position, 1.0);
}
