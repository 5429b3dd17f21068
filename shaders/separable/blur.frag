#version 330 core
// Separable SSS, one 1D blur pass (Jimenez et al. 2015; Freude 2014 Algorithm 4.1), run twice
// per kernel component r: u_direction = (1, 0), then (0, 1). Each pixel blurs with its own
// object's kernel (the object id of the diffuse target's alpha picks it), so objects never
// bleed into each other: a tap on another object is replaced by the centre colour.
//   Kernel scale, Freude eq. 4.11: k_sc = 1 / (tan(f_y / 2) p_d); a tap offset of o mm on the
//   surface lies o k_sc H / 2 pixels away (H the image height, p_d the view depth in mm).
//   Follow surface, eq. 4.12: s_c = o_c (1 - t) + i_c t with t = |i_d - o_d| / followSurfaceMm,
//   clamped to 0..1 (the paper's C SSS_w / tan(f_y / 2) made a length in mm).
//   Rank R, eq. 5.10: K = sum_r sign_r (a_r x a_r). The vertical pass multiplies component r's
//   result by sign_r; the caller adds the components' vertical passes (blending, r >= 1).
// Taps read the nearest texel, so ids and depths are never interpolated across an edge.

uniform sampler2D u_input;     // RGB diffuse radiance, a = object id
uniform sampler2D u_position;  // w = view depth, mm
uniform sampler2D u_kernels;   // RGBA32F, see SeparableMethod::post: row id = (components,
                               // followSurfaceMm, first component row); component rows =
                               // (sign RGB, taps), then the taps {w_R, w_G, w_B, offset_mm}
uniform sampler2D u_coverage;  // the radiance target; a = the pixel's coverage (MSAA)
uniform vec2 u_direction;      // unit, pixels
uniform float u_pixelsPerMmAtUnitDepth;  // (H / 2) / tan(f_y / 2): pixels per mm at 1 mm depth
uniform int u_component;                 // r, this pass pair's component of every kernel
uniform bool u_vertical;                 // the second pass: apply sign_r (and the coverage)
uniform bool u_coverageWeighted;         // MSAA: the resolved diffuse is one surface's own colour;
                                         // weight the result by coverage, as the tone map expects

layout(location = 0) out vec4 o_color;

// The pass's result: the vertical pass weights it by the pixel's coverage (linear, so the
// components' sum is weighted once).
vec4 finish(vec3 rgb, float id, ivec2 p) {
  if (u_vertical && u_coverageWeighted) rgb *= texelFetch(u_coverage, p, 0).a;
  return vec4(rgb, id);
}

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 centre = texelFetch(u_input, p, 0);
  int id = int(centre.a + 0.5);
  vec4 info = texelFetch(u_kernels, ivec2(0, id), 0);
  int components = int(info.x + 0.5);
  if (id == 0 || components == 0) {  // not a separable object: component 0 passes it through
    o_color = finish(u_component == 0 ? centre.rgb : vec3(0.0), centre.a, p);
    return;
  }
  if (u_component >= components) {  // a lower-rank object adds nothing in this pass pair
    o_color = vec4(0.0, 0.0, 0.0, centre.a);
    return;
  }
  int row = int(info.z + 0.5) + u_component;
  vec4 head = texelFetch(u_kernels, ivec2(0, row), 0);
  int taps = int(head.w + 0.5);
  float depth = texelFetch(u_position, p, 0).w;
  float pixelsPerMm = u_pixelsPerMmAtUnitDepth / max(depth, 1e-3);  // eq. 4.11
  ivec2 last = textureSize(u_input, 0) - 1;
  vec3 sum = vec3(0.0);
  for (int i = 0; i < taps; ++i) {
    vec4 k = texelFetch(u_kernels, ivec2(i + 1, row), 0);
    ivec2 q = clamp(ivec2(floor(gl_FragCoord.xy + u_direction * (k.w * pixelsPerMm))), ivec2(0), last);
    vec4 s = texelFetch(u_input, q, 0);
    vec3 color = s.rgb;
    if (int(s.a + 0.5) != id) {
      color = centre.rgb;
    } else if (info.y > 0.0) {
      float t = clamp(abs(texelFetch(u_position, q, 0).w - depth) / info.y, 0.0, 1.0);  // eq. 4.12
      color = mix(color, centre.rgb, t);
    }
    sum += k.rgb * color;
  }
  o_color = finish(u_vertical ? sum * head.rgb : sum, centre.a, p);  // eq. 5.10's sign_r
}
