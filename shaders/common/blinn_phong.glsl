// Blinn-Phong reflectance (Blinn 1977) for one light: Lambert diffuse plus a normalised
// half-vector lobe, (n + 8) / (8 pi) (Akenine-Moller et al., Real-Time Rendering 3rd ed.,
// eq. 7.49), so the highlight keeps its energy as the exponent changes.
// Returns the reflected fraction per unit incident radiance, times cos(theta).
vec3 blinnPhong(vec3 N, vec3 L, vec3 V, vec3 albedo, float specular, float shininess) {
  float NdotL = max(dot(N, L), 0.0);
  if (NdotL <= 0.0) return vec3(0.0);
  vec3 H = normalize(L + V);
  float NdotH = max(dot(N, H), 0.0);
  float lobe = (shininess + 8.0) / (8.0 * 3.14159265) * pow(NdotH, shininess);
  return (albedo / 3.14159265 + vec3(specular * lobe)) * NdotL * 3.14159265;
}

// The two halves of blinnPhong(), for methods that treat diffuse and specular apart
// (separable SSS blurs only the diffuse): Lambert diffuse times cos(theta), and the lobe.
vec3 lambertDiffuse(vec3 N, vec3 L, vec3 albedo) { return albedo * max(dot(N, L), 0.0); }

float blinnPhongSpecular(vec3 N, vec3 L, vec3 V, float specular, float shininess) {
  float NdotL = max(dot(N, L), 0.0);
  if (NdotL <= 0.0) return 0.0;
  vec3 H = normalize(L + V);
  float lobe = (shininess + 8.0) / (8.0 * 3.14159265) * pow(max(dot(N, H), 0.0), shininess);
  return specular * lobe * NdotL * 3.14159265;
}

// Blinn-Phong with wrap lighting (Green 2004, GPU Gems ch. 16): the diffuse is
// max(0, (N.L + w) / (1 + w)), reaching past the terminator as scattered light does; the
// specular keeps the plain N.L. w = 0 is blinnPhong().
vec3 blinnPhongWrap(vec3 N, vec3 L, vec3 V, vec3 albedo, float specular, float shininess, float wrap) {
  float NdotL = dot(N, L);
  float wrapped = max((NdotL + wrap) / (1.0 + wrap), 0.0);
  return albedo * wrapped + vec3(blinnPhongSpecular(N, L, V, specular, shininess));
}
