// Transmittance through thin parts (Jimenez et al. 2010, "Real-Time Realistic Skin
// Translucency"): the material's T(d) table, looked up with the light's path length inside the
// object from the shadow map (common/lights.glsl thicknessMm). Shared by the separable geometry
// pass and texture-space diffusion's irradiance pass, so both add the same back-lit light.
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

// The back-lit light of light i reaching P through the object (Jimenez et al. 2010):
// E T(d) saturate(0.3 + dot(-N, L)), d from the shadow map after pushing P inside along -Ng.
// 0 without a table or a shadow map.
vec3 transmittedLight(int i, vec3 P, vec3 Ng, vec3 L) {
  if (u_transmittanceRows <= 0 || u_lightShadowLayer[i] < 0) return vec3(0.0);
  float d = thicknessMm(i, P - Ng * u_transmissionShrinkMm);
  return transmittance(d) * u_lightRadiance[i] * clamp(0.3 + dot(-Ng, L), 0.0, 1.0);
}
