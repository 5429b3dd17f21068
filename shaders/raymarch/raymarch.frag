#version 330 core
// Ray-march method, fragment stage (François et al. 2006; Norberg 2010): single scattering
// through the layer stack, scaled by u_radianceScale, into the linear HDR radiance target (the
// pipeline's tone map comes last). Vertex stage: common/surface.vert (attribute 4 = the fitted
// plane (N_S, d mm), interpolated across the triangle as eq. 9 needs).
// Variants: TISSUE_ADAPTIVE (per-pixel sample count from view angle, layer depth and screen
// footprint, as subsurface::adaptiveSampleCount); TISSUE_SHOW_SAMPLES (radiance = samples / 100).

#include "common/surface.glsl"
#include "raymarch/march.glsl"

uniform int u_samples;          // fixed sample count (no TISSUE_ADAPTIVE)
uniform bool u_jitter;          // noisy sampling (Norberg §3.1.2) from a per-pixel hash
uniform uint u_seed;            // frame seed of the hash
uniform int u_viewportHeight;   // pixels, to number rows top-down like the CPU reference
uniform float u_radianceScale;  // unitless factor on the single-scattered radiance
uniform int u_minSamples, u_maxSamples;
uniform float u_depthResolution;  // mm, wanted depth step
uniform float u_texelsPerStep;    // wanted sideways step in texels (or pixels)
uniform float u_texelMm;          // mm per texel of the subsurface map
uniform float u_pixelAngle;       // radians per pixel, 2 tan(fov / 2) / height
uniform float u_cutoff;           // round-trip transmittance where the adaptive march stops
uniform float u_sigmaMin;         // smallest extinction of any layer and channel, mm^-1

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
  // A back face (a double-sided object, render::SceneObject::doubleSided) marches into the sheet
  // from its back: the surface normal and the local plane's normal are negated (the plane then
  // lies d below the back, eq. 14), as common/surface.glsl negates the shading normal.
  float facing = gl_FrontFacing ? 1.0 : -1.0;
  Frame f = makeFrame(v_worldPosition, u_cameraPosition - v_worldPosition, facing * v_normal, v_tangent,
                      vec4(facing * v_plane.xyz, v_plane.w), v_uv);
#ifdef TISSUE_ADAPTIVE
  int n = adaptiveSamples(f);
#else
  int n = u_samples;
#endif
  // The geometry pass's viewport starts at (0, 0) of the frame targets.
  uvec2 px = uvec2(gl_FragCoord.xy);
  px.y = uint(u_viewportHeight - 1) - px.y;
  float jitter = u_jitter ? pixelJitter(px.x, px.y, u_seed) : 0.5;
  vec4 result = marchSingleScattering(f, max(n, 1), jitter);
#ifdef TISSUE_SHOW_SAMPLES
  o_radiance = vec4(vec3(result.a / 100.0), 1.0);
#else
  o_radiance = vec4(result.rgb * u_radianceScale, 1.0);
#endif
  o_diffuse = vec4(0.0, 0.0, 0.0, u_objectId);
  o_position = surfacePosition();
}
