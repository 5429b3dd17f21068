#version 330 core
// Tone map: exposure, Reinhard (common/tonemap.glsl) and sRGB encoding of the HDR composite.
// Uncovered pixels get the background (sRGB, written as is), or are left alone.
// Variant TISSUE_WRITE_DEPTH (HostDepth::TestAndWrite): also writes the frame's depth where
// covered (the nearest sample with TISSUE_DEPTH_MS), so the host can depth-test what it draws
// after the tissue; uncovered pixels are always left alone.
#include "common/tonemap.glsl"
uniform sampler2D u_composite;  // linear HDR RGB, a = coverage
uniform float u_exposure;       // multiplies the radiance before the tone map
uniform vec3 u_background;      // sRGB-encoded
uniform bool u_writeBackground;
uniform ivec2 u_origin;         // pixels, the viewport's origin in the window
layout(location = 0) out vec4 o_color;

#ifdef TISSUE_WRITE_DEPTH
#ifdef TISSUE_DEPTH_MS
uniform sampler2DMS u_depth;  // the geometry passes' depth, multisampled
uniform int u_depthSamples;
float frameDepth(ivec2 p) {
  float d = 1.0;
  for (int i = 0; i < u_depthSamples; ++i) d = min(d, texelFetch(u_depth, p, i).r);
  return d;
}
#else
uniform sampler2D u_depth;    // the geometry passes' depth
float frameDepth(ivec2 p) { return texelFetch(u_depth, p, 0).r; }
#endif
#endif

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy) - u_origin;
  vec4 c = texelFetch(u_composite, p, 0);
#ifdef TISSUE_WRITE_DEPTH
  if (c.a <= 0.0) discard;
  gl_FragDepth = frameDepth(p);
#endif
  if (c.a <= 0.0) {
    if (!u_writeBackground) discard;
    o_color = vec4(u_background, 1.0);
    return;
  }
  // MSAA edges arrive premultiplied by their coverage a: map the surface's own colour, then
  // blend it over the background by coverage (as resolving tone-mapped samples would).
  vec3 mapped = linearToSrgb(tonemapReinhard(c.rgb / c.a * u_exposure));
  o_color = vec4(u_writeBackground ? mix(u_background, mapped, min(c.a, 1.0)) : mapped, 1.0);
}
