#version 330 core
// Tone map: exposure, Reinhard (common/tonemap.glsl) and sRGB encoding of the HDR composite.
// Uncovered pixels get the background (sRGB, written as is), or are left alone.
#include "common/tonemap.glsl"
uniform sampler2D u_composite;  // linear HDR RGB, a = coverage
uniform float u_exposure;       // multiplies the radiance before the tone map
uniform vec3 u_background;      // sRGB-encoded
uniform bool u_writeBackground;
uniform ivec2 u_origin;         // pixels, the viewport's origin in the window
layout(location = 0) out vec4 o_color;
void main() {
  vec4 c = texelFetch(u_composite, ivec2(gl_FragCoord.xy) - u_origin, 0);
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
