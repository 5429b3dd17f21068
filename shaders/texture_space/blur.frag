#version 330 core
// Texture-space diffusion, one separable Gaussian pass (d'Eon et al. 2007): a 1D Gaussian of
// standard deviation u_sigmaMm (mm on the surface) along u or v, its step in texture space set
// per texel by the stretch map. Maps are premultiplied by alpha (1 where the surface was drawn
// and visible, 0 in gutters and culled or clipped texels), and the sum is normalised by the
// alpha it gathered, so empty texels neither darken the result nor leak into it.

in vec2 v_texCoord;

uniform sampler2D u_source;   // rgb: irradiance times a; a: 1 where valid
uniform sampler2D u_stretch;  // r, g: mm per UV unit along u, v
uniform vec2 u_direction;     // (1, 0) or (0, 1)
uniform float u_sigmaMm;      // mm
uniform float u_mapScale;     // s of Jimenez eq. 3: texture coordinates span [0, s]
uniform int u_skipEmpty;      // 1: no convolution where alpha is 0 (Jimenez §3, Listing 3)
const int kMaxTaps = 17;
uniform int u_tapCount;                // 2 h + 1 <= kMaxTaps
uniform float u_tapOffsets[kMaxTaps];  // in standard deviations
uniform float u_tapWeights[kMaxTaps];  // sum to 1
uniform float u_maxCoord;              // s - half a texel: taps stay inside this frame's map

out vec4 o_color;

void main() {
  vec4 centre = texture(u_source, v_texCoord);
  if (u_skipEmpty == 1 && centre.a <= 0.0) {
    o_color = vec4(0.0);
    return;
  }
  vec2 stretch = texture(u_stretch, v_texCoord).rg;
  float mmPerUv = max(dot(stretch, u_direction), 1e-6);
  vec2 step = u_direction * (u_sigmaMm / mmPerUv * u_mapScale);
  vec4 sum = vec4(0.0);
  for (int i = 0; i < u_tapCount; ++i) {
    vec4 s = texture(u_source, clamp(v_texCoord + step * u_tapOffsets[i], vec2(0.0), vec2(u_maxCoord)));
    sum += u_tapWeights[i] * s;
  }
  o_color = vec4(sum.a > 1e-6 ? sum.rgb / sum.a * centre.a : vec3(0.0), centre.a);
}
