// Lambert diffuse plus the outer surface's specular (common/specular.glsl: the truth's
// microfacet reflection) for one light. The name stays from its first form, Blinn-Phong (Blinn
// 1977): its `shininess` is still the Blinn-Phong exponent that the microfacet roughness stands for.
// Returns the reflected fraction per unit incident radiance, times cos(theta), times pi.
#include "common/specular.glsl"

// Lambert diffuse times cos(theta): the half of blinnPhong() that separable SSS blurs.
vec3 lambertDiffuse(vec3 N, vec3 L, vec3 albedo) { return albedo * max(dot(N, L), 0.0); }

vec3 blinnPhong(vec3 N, vec3 L, vec3 V, vec3 albedo, float specular, float shininess) {
  return lambertDiffuse(N, L, albedo) + vec3(surfaceSpecular(N, L, V, specular, shininess));
}

// Wrap lighting (Green 2004, GPU Gems ch. 16): the diffuse is max(0, (N.L + w) / (1 + w)),
// reaching past the terminator as scattered light does; the specular keeps the plain N.L.
// The diffuse leaves through the outer surface with `exitWeight` (common/specular.glsl
// boundaryWeight at the eye's cosine). w = 0 and exitWeight = 1 is blinnPhong().
vec3 blinnPhongWrap(vec3 N, vec3 L, vec3 V, vec3 albedo, float specular, float shininess, float wrap,
                    float exitWeight) {
  float NdotL = dot(N, L);
  float wrapped = max((NdotL + wrap) / (1.0 + wrap), 0.0);
  return albedo * wrapped * exitWeight + vec3(surfaceSpecular(N, L, V, specular, shininess));
}
