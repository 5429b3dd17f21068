#version 330 core
// Separable SSS, MSAA resolve of the diffuse and position targets (replacing the averaging
// blit for the blur). Averaging a silhouette pixel's samples mixes the surface with the
// background's zeros: its object id, view depth and world position become values no surface
// has, and its diffuse is darkened by the coverage, which the blur would then spread inward.
// Here each pixel keeps the nearest covered sample's id, position and depth (a real surface
// point), and the mean diffuse of the samples of that object only (its own colour). The blur's
// vertical pass weights the result by the pixel's coverage (radiance a), as the blit did.
uniform sampler2DMS u_diffuse;   // RGB diffuse radiance, a = object id (0: none)
uniform sampler2DMS u_position;  // xyz world mm, w view depth mm (0: no surface)
uniform int u_samples;           // samples per pixel

layout(location = 1) out vec4 o_diffuse;
layout(location = 2) out vec4 o_position;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  int nearest = -1;
  float depth = 0.0;
  for (int s = 0; s < u_samples; ++s) {
    float d = texelFetch(u_position, p, s).w;
    if (d > 0.0 && (nearest < 0 || d < depth)) {
      nearest = s;
      depth = d;
    }
  }
  if (nearest < 0) {  // background only
    o_diffuse = vec4(0.0);
    o_position = vec4(0.0);
    return;
  }
  float id = texelFetch(u_diffuse, p, nearest).a;
  vec3 sum = vec3(0.0);
  float n = 0.0;
  for (int s = 0; s < u_samples; ++s) {
    vec4 d = texelFetch(u_diffuse, p, s);
    if (abs(d.a - id) < 0.5 && texelFetch(u_position, p, s).w > 0.0) {
      sum += d.rgb;
      n += 1.0;
    }
  }
  o_diffuse = vec4(sum / n, id);
  o_position = texelFetch(u_position, p, nearest);
}
