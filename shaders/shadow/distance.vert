#version 330 core
// Shadow pass, vertex stage: object (mm) through the model matrix to the light's clip space.
layout(location = 0) in vec3 a_position;  // mm, object space
uniform mat4 u_model;                     // object (mm) to world (mm)
uniform mat4 u_shadowMatrix;              // world (mm) to the shadow map's clip space
out vec3 v_worldPosition;
void main() {
  v_worldPosition = (u_model * vec4(a_position, 1.0)).xyz;
  gl_Position = u_shadowMatrix * vec4(v_worldPosition, 1.0);
}
