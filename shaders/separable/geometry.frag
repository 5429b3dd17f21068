#version 330 core
// Separable SSS, geometry pass (Jimenez et al. 2015; Freude 2014 §4.2): the diffuse light goes
// to the diffuse target, to be blurred by separable/blur.frag; the specular goes to the radiance
// target and is added after the blur (post/composite.frag). Texturing is pre-scatter: the
// diffuse target holds albedo x irradiance, so the blur also softens the base colour's detail.
// Transmission through thin parts (Jimenez et al. 2010, "Real-Time Realistic Skin
// Translucency"): the light's path length inside the object, from the shadow map, looks up the
// material's transmittance T(d); the back-lit term E T(d) albedo saturate(0.3 + dot(-N, L)) is
// added to the diffuse before the blur, so the blur spreads it too (Freude §4.4).

#include "common/surface.glsl"
#include "common/blinn_phong.glsl"
#include "common/lights.glsl"

#define MAX_TRANSMITTANCE_ROWS 16
uniform int u_transmittanceRows;                         // 0 = no transmission
uniform vec4 u_transmittance[MAX_TRANSMITTANCE_ROWS];    // {T_R, T_G, T_B, thickness mm}, increasing
uniform float u_transmissionShrinkMm;                    // mm pushed inside before the lookup

// T(d) by linear interpolation in the table, clamped at both ends.
vec3 transmittance(float d) {
  if (d <= u_transmittance[0].w) return u_transmittance[0].rgb;
  for (int i = 1; i < u_transmittanceRows; ++i) {
    vec4 a = u_transmittance[i - 1], b = u_transmittance[i];
    if (d <= b.w) return mix(a.rgb, b.rgb, (d - a.w) / max(b.w - a.w, 1e-6));
  }
  return u_transmittance[u_transmittanceRows - 1].rgb;
}

void main() {
  vec3 N = surfaceNormal();
  vec3 Ng = normalize(v_normal);
  vec3 albedo = surfaceAlbedo();
  vec3 V = normalize(u_cameraPosition - v_worldPosition);
  vec3 diffuse = u_ambient * albedo;
  vec3 specular = vec3(0.0);
  for (int i = 0; i < u_lightCount; ++i) {
    vec3 L = lightDirection(i, v_worldPosition);
    vec3 E = u_lightRadiance[i] * shadowFactor(i, v_worldPosition, Ng);
    diffuse += lambertDiffuse(N, L, albedo) * E;
    specular += blinnPhongSpecular(N, L, V, u_specular, u_shininess) * E;
    if (u_transmittanceRows > 0 && u_lightShadowLayer[i] >= 0) {
      float d = thicknessMm(i, v_worldPosition - Ng * u_transmissionShrinkMm);
      diffuse += transmittance(d) * u_lightRadiance[i] * albedo * clamp(0.3 + dot(-Ng, L), 0.0, 1.0);
    }
  }
  o_radiance = vec4(specular, 1.0);
  o_diffuse = vec4(diffuse, u_objectId);
  o_position = surfacePosition();
}
