// The outer surface's reflection of a light: the microfacet model the path-traced truth uses
// (libtissue/src/truth/transport.cpp, Transport::glossy), so that every method's highlight is the
// truth's. Walter et al. 2007: Beckmann distribution D (eq. 25), the rational approximation of
// Smith's G1 (eq. 27), f_r = F G D / (4 |N.L| |N.V|) (eq. 20), and the exact unpolarised Fresnel
// reflectance of a dielectric at the half vector (eq. 22).
//   specular:  the reflectance at normal incidence, F0 = ((n - 1) / (n + 1))^2 (a material of
//              index n seen from air; tissue n = 1.38: F0 = 0.0255), 0..0.99
//   shininess: the Blinn-Phong exponent s it stands for; Beckmann alpha = sqrt(2 / (s + 2))
//              (Walter et al. 2007 §5.2; scene::roughnessOf gives the truth the same alpha)
// Returns f_r cos(theta_L) pi: the reflected radiance per unit light radiance (the renderer's
// lights have irradiance pi * radiance on a surface facing them).

// Walter et al. 2007 eq. 22: c = cos of the angle to the half vector, n = relative index.
float dielectricFresnel(float c, float n) {
  float g2 = n * n - 1.0 + c * c;
  if (g2 <= 0.0) return 1.0;  // total internal reflection
  float g = sqrt(g2);
  float a = (g - c) / (g + c);
  float b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
  return 0.5 * a * a * (1.0 + b * b);
}

// The weight of diffuse light leaving through the outer surface at cosine mu = N.V, relative to
// leaving along the normal: T(mu) / T(1), with T = 1 - F the dielectric's transmittance (eq. 22;
// `specular` is F0 = F(1); 0: no boundary, weight 1). Light scattered inside reaches the eye
// through the boundary at the eye's angle (over the geometric normal: the macro surface it crosses),
// so an oblique view sees less of it than Lambert does
// (Jensen et al. 2001's F_t(eta, w_o); the ray march's T(N.V)/T0, raymarch/raymarch.frag).
// Against the path-traced truth (docs/DECISIONS.md, eighth session) it lowered every painted
// method's error on every lit atlas frame and on the budget bench; the same weight at the
// light's entry, T(N.L)/T0, helped two atlas frames and hurt the grazing one and the bench (at
// oblique incidence the shallower path also returns more light, which that weight alone omits).
float boundaryWeight(float mu, float specular) {
  if (specular <= 0.0) return 1.0;
  float r = sqrt(min(specular, 0.99));
  return (1.0 - dielectricFresnel(clamp(mu, 0.0, 1.0), (1.0 + r) / (1.0 - r))) / (1.0 - specular);
}

// Walter et al. 2007 eq. 27.
float smithG1Beckmann(float cosine, float alpha) {
  float t = sqrt(max(0.0, 1.0 - cosine * cosine)) / cosine;
  if (t <= 0.0) return 1.0;
  float a = 1.0 / (alpha * t);
  return a < 1.6 ? (3.535 * a + 2.181 * a * a) / (1.0 + 2.276 * a + 2.577 * a * a) : 1.0;
}

float surfaceSpecular(vec3 N, vec3 L, vec3 V, float specular, float shininess) {
  float NdotL = dot(N, L), NdotV = dot(N, V);
  if (NdotL <= 0.0 || NdotV <= 0.0 || specular <= 0.0) return 0.0;
  vec3 H = normalize(L + V);
  float NdotH = dot(N, H);
  if (NdotH <= 0.0) return 0.0;
  float alpha = sqrt(2.0 / (max(shininess, 0.0) + 2.0));
  float a2 = alpha * alpha, c2 = NdotH * NdotH;
  float D = exp(-(1.0 - c2) / (c2 * a2)) / (3.14159265 * a2 * c2 * c2);
  float r = sqrt(min(specular, 0.99));
  float F = dielectricFresnel(max(dot(V, H), 0.0), (1.0 + r) / (1.0 - r));
  float G = smithG1Beckmann(NdotV, alpha) * smithG1Beckmann(NdotL, alpha);
  return F * D * G / (4.0 * NdotV) * 3.14159265;
}
