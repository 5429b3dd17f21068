#version 330 core
// Texture-space diffusion, final pass: the diffuse radiance is the weighted sum of the blurred
// irradiance maps (d'Eon et al.: R = sum_i w_i G(v_i)), times the albedo (post-scatter
// texturing), plus the specular reflection of the surface; tone-mapped like the lit pass.
#include "texture_space/light.glsl"
#include "common/tonemap.glsl"

const int kMaxGaussians = 8;

in vec3 v_worldPosition;
in vec3 v_normal;
in vec2 v_uv;
in vec2 v_mapCoord;

uniform sampler2D u_baseColor;                 // sRGB albedo
uniform sampler2D u_maps[kMaxGaussians];   // blurred irradiance, one per Gaussian
uniform vec3 u_weights[kMaxGaussians];     // w_i per channel
uniform int u_gaussianCount;
uniform vec3 u_cameraPosition;  // mm
uniform float u_exposure;
uniform int u_output;  // 0: tone-mapped colour; 1: linear diffuse radiance (for references)

out vec4 o_color;

vec3 term(sampler2D map, int i) {
  if (i >= u_gaussianCount) return vec3(0.0);
  vec4 m = texture(map, v_mapCoord);
  return u_weights[i] * (m.a > 1e-4 ? m.rgb / m.a : vec3(0.0));
}

void main() {
  // Sampler arrays take constant indices only (GLSL 3.30), hence one line per term. Maps are
  // premultiplied by coverage: dividing by the filtered alpha keeps gutter texels out of the
  // bilinear lookup, so chart seams do not darken.
  vec3 diffuse = term(u_maps[0], 0) + term(u_maps[1], 1) + term(u_maps[2], 2) + term(u_maps[3], 3) +
                 term(u_maps[4], 4) + term(u_maps[5], 5) + term(u_maps[6], 6) + term(u_maps[7], 7);
  vec3 albedo = srgbToLinear(texture(u_baseColor, v_uv).rgb);
  if (u_output == 1) {
    o_color = vec4(diffuse, 1.0);
    return;
  }
  vec3 n = normalize(v_normal);
  vec3 radiance = albedo * diffuse + tsdSpecular(v_worldPosition, n, u_cameraPosition);
  o_color = vec4(linearToSrgb(tonemapReinhard(radiance * u_exposure)), 1.0);
}
