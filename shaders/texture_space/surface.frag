#version 330 core
// Texture-space diffusion in the render pipeline, camera pass: the object's diffused diffuse
// radiance (the combined map, texture_space/combine.frag, times albedo^(1 - p) for the
// post-scatter part of the texturing) goes to the diffuse target with the object id, where the
// separable blur leaves it as it is; the specular goes to the radiance target, lit by every
// light with its shadow as in the separable geometry pass. The composite adds the two, so
// FrameView::BlurredDiffuse holds both methods' subsurface diffuse.
#include "common/surface.glsl"
#include "common/blinn_phong.glsl"
#include "common/lights.glsl"

uniform sampler2D u_diffused;       // rgb: sum_i w_i map_i (premultiplied by a = coverage)
uniform float u_mapScale;           // s of Jimenez eq. 3: the maps' used part is [0, s]^2
uniform float u_albedoPreScatter;   // p

void main() {
  vec3 N = surfaceNormal();
  vec3 Ng = geometricNormal();
  vec3 V = normalize(u_cameraPosition - v_worldPosition);
  // Dividing by the filtered coverage keeps gutter texels out of the bilinear lookup.
  vec4 m = texture(u_diffused, v_uv * u_mapScale);
  vec3 diffused = m.a > 1e-4 ? m.rgb / m.a : vec3(0.0);
  vec3 albedo = surfaceAlbedo();
  vec3 specular = vec3(0.0);
  for (int i = 0; i < u_lightCount; ++i) {
    vec3 L = lightDirection(i, v_worldPosition);
    specular += surfaceSpecular(N, L, V, u_specular, u_shininess) * u_lightRadiance[i] *
                shadowFactor(i, v_worldPosition, Ng);
  }
  o_radiance = vec4(specular, 1.0);
  // The diffused light leaves through the boundary here, where it exits (common/specular.glsl
  // boundaryWeight).
  o_diffuse = vec4(diffused * pow(max(albedo, vec3(1e-6)), vec3(1.0 - u_albedoPreScatter)) *
                       boundaryWeight(dot(Ng, V), u_specular),  // Ng: as lit/lit.frag
                   u_objectId);
  o_position = surfacePosition();
}
