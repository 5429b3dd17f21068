#version 330 core
// Texture-space diffusion: the diffuse profile's sum R = sum_i w_i G(v_i) (d'Eon et al. 2007)
// as one map, so the camera pass samples one texture instead of one per Gaussian. Texel by
// texel over the used T x T square; maps stay premultiplied by coverage (a, the same in all).
const int kMaxGaussians = 8;
uniform sampler2D u_maps[kMaxGaussians];  // blurred irradiance, one per Gaussian (units 0..7)
uniform vec3 u_weights[kMaxGaussians];    // w_i per channel; 0 for unused slots
uniform int u_gaussianCount;

out vec4 o_color;

vec4 term(sampler2D map, int i) {
  if (i >= u_gaussianCount) return vec4(0.0);
  vec4 m = texelFetch(map, ivec2(gl_FragCoord.xy), 0);
  return vec4(u_weights[i] * m.rgb, m.a);
}

void main() {
  // Sampler arrays take constant indices only (GLSL 3.30), hence one call per term.
  vec4 t[kMaxGaussians] = vec4[](term(u_maps[0], 0), term(u_maps[1], 1), term(u_maps[2], 2), term(u_maps[3], 3),
                                 term(u_maps[4], 4), term(u_maps[5], 5), term(u_maps[6], 6), term(u_maps[7], 7));
  vec3 sum = vec3(0.0);
  for (int i = 0; i < kMaxGaussians; ++i)
    sum += t[i].rgb;
  o_color = vec4(sum, t[0].a);
}
