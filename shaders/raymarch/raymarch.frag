#version 330 core
// Ray-marched subsurface texture mapping, fragment stage (François et al. 2006; Norberg 2010):
// single scattering through the layer stack, then exposure, tone map and sRGB.
// Variants: TISSUE_ADAPTIVE (per-pixel sample count from view angle, layer depth and screen
// footprint, as subsurface::adaptiveSampleCount); TISSUE_SHOW_SAMPLES (write samples / 100).

#include "raymarch/march.glsl"
#include "common/tonemap.glsl"

in vec3 v_worldPosition;
in vec3 v_normal;
in vec4 v_tangent;
in vec2 v_uv;
in vec4 v_plane;

uniform vec3 u_cameraPosition;  // mm
uniform int u_samples;          // fixed sample count (no TISSUE_ADAPTIVE)
uniform bool u_jitter;          // noisy sampling (Norberg §3.1.2) from a per-pixel hash
uniform uint u_seed;            // frame seed of the hash
uniform int u_viewportHeight;   // pixels, to number rows top-down like the CPU reference
uniform vec2 u_viewportOrigin;  // pixels
uniform float u_exposure;       // multiplies the radiance before the tone map
uniform int u_minSamples, u_maxSamples;
uniform float u_depthResolution;  // mm, wanted depth step
uniform float u_texelsPerStep;    // wanted sideways step in texels (or pixels)
uniform float u_texelMm;          // mm per texel of the subsurface map
uniform float u_pixelAngle;       // radians per pixel, 2 tan(fov / 2) / height
uniform float u_cutoff;           // round-trip transmittance where the adaptive march stops
uniform float u_sigmaMin;         // smallest extinction of any layer and channel, mm^-1

layout(location = 0) out vec4 o_color;

// Adaptive quality, as subsurface::adaptiveMarch: march only as deep as light returns from
// (round-trip transmittance above u_cutoff), as finely as depth and footprint need.
int adaptiveSamples(inout Frame f) {
  float roundTrip = -log(u_cutoff) / (u_sigmaMin * (1.0 + f.cosDepth));
  f.tMax = min(f.tMax, roundTrip);
  float depthMm = f.tMax * f.cosDepth;
  float lateralMm = f.tMax * sqrt(max(1.0 - f.cosDepth * f.cosDepth, 0.0));
  float pixelMm = distance(u_cameraPosition, f.P) * u_pixelAngle / max(dot(f.Np, f.wo), 0.1);
  float stepMm = u_texelsPerStep * max(u_texelMm, pixelMm);
  float want = max(depthMm / u_depthResolution, lateralMm / stepMm);
  return clamp(int(ceil(want)), u_minSamples, u_maxSamples);
}

void main() {
  Frame f = makeFrame(v_worldPosition, u_cameraPosition - v_worldPosition, v_normal, v_tangent, v_plane, v_uv);
#ifdef TISSUE_ADAPTIVE
  int n = adaptiveSamples(f);
#else
  int n = u_samples;
#endif
  uvec2 px = uvec2(gl_FragCoord.xy - u_viewportOrigin);
  px.y = uint(u_viewportHeight - 1) - px.y;
  float jitter = u_jitter ? pixelJitter(px.x, px.y, u_seed) : 0.5;
  vec4 result = marchSingleScattering(f, max(n, 1), jitter);
#ifdef TISSUE_SHOW_SAMPLES
  o_color = vec4(vec3(result.a / 100.0), 1.0);
#else
  o_color = vec4(linearToSrgb(tonemapReinhard(result.rgb * u_exposure)), 1.0);
#endif
}
