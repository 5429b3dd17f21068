#version 330 core
// Ray-march method, fragment stage (François et al. 2006; Norberg 2010): single scattering
// through the layer stack, scaled by u_radianceScale, into the linear HDR radiance target (the
// pipeline's tone map comes last). Vertex stage: common/surface.vert (attribute 4 = the fitted
// plane (N_S, d mm), interpolated across the triangle as eq. 9 needs).
// With a boundary (u_ior > 1) the pixel is composed as François et al. 2006 §3 add a specular
// (glossy) and a diffuse reflection to the single scattering, and as Norberg 2010 §2.2.2 light
// "scatters directly towards the viewer" (a specular term) or "into the material":
//   L = f_r (N.L) E                                                 outer surface (common/specular.glsl)
//     + T(N.V) [ L_ss(T(N.L) (N.L) / mu'_L per light) / n^2         single scattering (eq. 1-5)
//              + sum_l R_ms (N.L) E_l/pi / T0 ]                    multiple scattering
// with T(mu) = 1 - F(mu) the dielectric's transmittance and T0 = T(1): the dipole's R_ms is per
// incident light at normal incidence; T(N.V)/T0 carries its exit to other view angles. Its entry
// keeps R_ms at every light angle: at oblique incidence the boundary passes less light
// (T(N.L)/T0), but that light starts shallower and more of it returns (Chandrasekhar's H-function:
// a half-space of albedo near 1 reflects more at oblique incidence), and for tissue's albedos the
// two nearly cancel. With T(N.L)/T0 the march was 10 % dark where the light met the surface
// obliquely; without it its error fell on every atlas frame and on the budget bench
// (docs/DECISIONS.md, "The ray march's multiple scattering enters without the Fresnel weight"),
// as the painted methods' had (common/specular.glsl boundaryWeight). The single
// scattering is marched along the refracted view path and lit along the refracted light paths
// (march.glsl, insideDirection), as the truth's closed form (truth::layeredSlabSingleScattering,
// Hanrahan and Krueger 1993 §4): each beam narrows by (N.L) / mu'_L entering, mu' the refracted
// cosine, and the radiance leaving spreads over n^2 the solid angle. François et al. march
// straight, without a boundary; straight paths through one at grazing view are up to
// 1 / cos(theta) long where the refracted ones are at most 1 / cos(critical angle) (1.4 for
// n = 1.4), which made the march too bright at oblique view. At normal light and view the sum is
// exactly R_ms + pi L_ss / E (optics::semiInfiniteReflectance).
// Variants: TISSUE_ADAPTIVE (per-pixel sample count from view angle, layer depth and screen
// footprint, as subsurface::adaptiveSampleCount); TISSUE_SHOW_SAMPLES (radiance = samples / 100).

#include "common/surface.glsl"
#include "raymarch/march.glsl"
#include "common/specular.glsl"

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
uniform bool u_specularOn;        // the outer surface's Fresnel-weighted lobe

// Adaptive quality, as subsurface::adaptiveMarch: march only as deep as light returns from
// (round-trip transmittance above u_cutoff), as finely as depth and footprint need.
int adaptiveSamples(inout Frame f, float cosView) {
  float roundTrip = -log(u_cutoff) / (u_sigmaMin * (1.0 + f.cosDepth));
  f.tMax = min(f.tMax, roundTrip);
  float depthMm = f.tMax * f.cosDepth;
  float lateralMm = f.tMax * sqrt(max(1.0 - f.cosDepth * f.cosDepth, 0.0));
  float pixelMm = distance(u_cameraPosition, f.P) * u_pixelAngle / max(cosView, 0.1);
  float stepMm = u_texelsPerStep * max(u_texelMm, pixelMm);
  float want = max(depthMm / u_depthResolution, lateralMm / stepMm);
  return clamp(int(ceil(want)), u_minSamples, u_maxSamples);
}

void main() {
  // A back face (a double-sided object, render::SceneObject::doubleSided) marches into the sheet
  // from its back: the surface normal and the local plane's normal are negated (the plane then
  // lies d below the back, eq. 14), as common/surface.glsl negates the shading normal.
  // The frame's view direction is the refracted one inside (insideDirection); the boundary's
  // weights and the specular below take the view outside, V.
  float facing = gl_FrontFacing ? 1.0 : -1.0;
  vec3 V = normalize(u_cameraPosition - v_worldPosition);
  vec3 N = normalize(facing * v_normal);
  Frame f = makeFrame(v_worldPosition, insideDirection(V, N), N, v_tangent, vec4(facing * v_plane.xyz, v_plane.w),
                      v_uv);
#ifdef TISSUE_ADAPTIVE
  int n = adaptiveSamples(f, dot(N, V));
#else
  int n = u_samples;
#endif
  // The geometry pass's viewport starts at (0, 0) of the frame targets.
  uvec2 px = uvec2(gl_FragCoord.xy);
  px.y = uint(u_viewportHeight - 1) - px.y;
  float jitter = u_jitter ? pixelJitter(px.x, px.y, u_seed) : 0.5;
  bool boundary = u_ior > 1.0;
  float F0 = boundary ? ((u_ior - 1.0) / (u_ior + 1.0)) * ((u_ior - 1.0) / (u_ior + 1.0)) : 0.0;
  float NdotV = max(dot(N, V), 0.0);
  float T0 = 1.0 - F0;
  // The boundary's transmittances T(mu) = T0 x boundaryWeight(mu): the exact dielectric Fresnel
  // (Walter et al. 2007 eq. 22, common/specular.glsl) that the optics deriving the layers' albedos
  // (optics/reflectance.cpp), the path-traced truth and the painted methods' exit weight use.
  float Tv = boundary ? T0 * boundaryWeight(NdotV, F0) : 1.0;
  float weight[MAX_LIGHTS];
  vec3 irradianceIn = vec3(0.0), specular = vec3(0.0);
  for (int l = 0; l < MAX_LIGHTS; ++l) {
    weight[l] = 1.0;
    if (l >= u_lightCount) continue;
    // Cast shadows at the surface point, as every other method's (common/lights.glsl): the light
    // the march collects enters within a few mean free paths of it, far less than a shadow map
    // texel. Before, the march drew none, though the truth and every other method do
    // (docs/DECISIONS.md, "The ray march draws cast shadows").
    float shadow = shadowFactor(l, v_worldPosition, N);
    weight[l] = shadow;
    if (!boundary) continue;
    vec3 L = lightDirection(l, f.P);
    float NdotL = max(dot(N, L), 0.0);
    float Tl = T0 * boundaryWeight(NdotL, F0);
    weight[l] = shadow * Tl * NdotL / max(insideCosine(NdotL), 1e-4);  // the beam narrowed by refraction
    irradianceIn += shadow * NdotL * u_lightRadiance[l];  // no T(N.L)/T0: see the header
    // The outer surface's microfacet reflection, every method's (common/specular.glsl).
    if (u_specularOn) specular += shadow * surfaceSpecular(N, L, V, F0, u_shininess) * u_lightRadiance[l];
  }
  vec4 result = marchSingleScattering(f, max(n, 1), jitter, weight);
#ifdef TISSUE_SHOW_SAMPLES
  o_radiance = vec4(vec3(result.a / 100.0), 1.0);
#else
  vec3 radiance = result.rgb * u_radianceScale;
  if (boundary) {
    float b[8];
    sampleBoundaries(f.uv, b);
    radiance = specular + Tv * (radiance / (u_ior * u_ior) + multipleScatteringAlbedo(b) * irradianceIn / T0);
  }
  o_radiance = vec4(radiance, 1.0);
#endif
  o_diffuse = vec4(0.0, 0.0, 0.0, u_objectId);
  o_position = surfacePosition();
}
