#version 330 core
// Separable SSS, one 1D blur pass (Jimenez et al. 2015; Freude 2014 Algorithm 4.1), run twice:
// u_direction = (1, 0), then (0, 1). Each pixel blurs with its own object's kernel (row = the
// object id of the diffuse target's alpha), so objects never bleed into each other: a tap on
// another object is replaced by the centre colour.
//   Kernel scale, Freude eq. 4.11: k_sc = 1 / (tan(f_y / 2) p_d); a tap offset of o mm on the
//   surface lies o k_sc H / 2 pixels away (H the image height, p_d the view depth in mm).
//   Follow surface, eq. 4.12: s_c = o_c (1 - t) + i_c t with t = |i_d - o_d| / followSurfaceMm,
//   clamped to 0..1 (the paper's C SSS_w / tan(f_y / 2) made a length in mm).
// Taps read the nearest texel, so ids and depths are never interpolated across an edge.

uniform sampler2D u_input;     // RGB diffuse radiance, a = object id
uniform sampler2D u_position;  // w = view depth, mm
uniform sampler2D u_kernels;   // RGBA32F; row = object id; texel 0 = (taps, followSurfaceMm), then the taps
uniform vec2 u_direction;      // unit, pixels
uniform float u_pixelsPerMmAtUnitDepth;  // (H / 2) / tan(f_y / 2): pixels per mm at 1 mm depth

layout(location = 0) out vec4 o_color;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 centre = texelFetch(u_input, p, 0);
  int id = int(centre.a + 0.5);
  vec4 info = texelFetch(u_kernels, ivec2(0, id), 0);
  int taps = int(info.x + 0.5);
  if (id == 0 || taps == 0) {
    o_color = centre;
    return;
  }
  float depth = texelFetch(u_position, p, 0).w;
  float pixelsPerMm = u_pixelsPerMmAtUnitDepth / max(depth, 1e-3);  // eq. 4.11
  ivec2 last = textureSize(u_input, 0) - 1;
  vec3 sum = vec3(0.0);
  for (int i = 0; i < taps; ++i) {
    vec4 k = texelFetch(u_kernels, ivec2(i + 1, id), 0);
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
  o_color = vec4(sum, centre.a);
}
