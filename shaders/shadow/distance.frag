#version 330 core
// Shadow pass, fragment stage: the distance (mm) from the light, nearest surface kept by the
// depth test.
#include "common/light_distance.glsl"
in vec3 v_worldPosition;
uniform vec4 u_light;  // see lightDistance()
layout(location = 0) out float o_distance;
void main() { o_distance = lightDistance(u_light, v_worldPosition); }
