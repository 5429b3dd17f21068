#version 330 core
// Lit method: base colour texture, tangent-space normal map, Blinn-Phong from every light
// with its shadow, into the linear HDR radiance target (the tone map comes last, in
// post/tonemap.frag). Writes no separable diffuse.

#include "common/surface.glsl"
#include "common/blinn_phong.glsl"
#include "common/lights.glsl"

uniform float u_wrap;  // LitSettings::wrap, 0: Lambert

void main() {
  vec3 N = surfaceNormal();
  vec3 Ng = geometricNormal();
  vec3 albedo = surfaceAlbedo();
  vec3 V = normalize(u_cameraPosition - v_worldPosition);
  // The diffuse leaves through the outer surface at the eye's angle (boundaryWeight), over the
  // geometric normal: a normal map's detail turns N away from the eye near the outline.
  float exitWeight = boundaryWeight(dot(Ng, V), u_specular);
  vec3 color = u_ambient * albedo * exitWeight;
  for (int i = 0; i < u_lightCount; ++i) {
    vec3 L = lightDirection(i, v_worldPosition);
    color += blinnPhongWrap(N, L, V, albedo, u_specular, u_shininess, u_wrap, exitWeight) * u_lightRadiance[i] *
             shadowFactor(i, v_worldPosition, Ng);
  }
  o_radiance = vec4(color, 1.0);
  o_diffuse = vec4(0.0, 0.0, 0.0, u_objectId);
  o_position = surfacePosition();
}
