// Single scattering by ray marching (François et al. 2006 eq. 5, Algorithms 1 and 2; Norberg
// 2010 §2.1, §3.1). The same model, step for step, as the CPU code in
// libtissue/src/subsurface/single_scattering.cpp (plane mode); keep the two in step.
// Lengths in mm, coefficients in mm^-1. The lights are the scene's (common/lights.glsl): a point
// light's direction is taken per sample M, a directional light's is the same everywhere.

#include "common/lights.glsl"

#define TISSUE_MAX_LAYERS 9      // 4N + 1 for N <= 2 RGBA maps
#define TISSUE_MAX_SAMPLES 256

uniform int u_layerCount;                      // 4N + 1
uniform int u_boundaryCount;                   // 4N
uniform vec3 u_sigmaS[TISSUE_MAX_LAYERS];      // mm^-1
uniform vec3 u_sigmaT[TISSUE_MAX_LAYERS];      // mm^-1
uniform float u_schlickK[TISSUE_MAX_LAYERS];   // Schlick k per layer
uniform vec3 u_multipleAlbedo[TISSUE_MAX_LAYERS];  // multiple-scattered reflectance per layer (0: none)
uniform vec3 u_sigmaTr[TISSUE_MAX_LAYERS];     // effective transport coefficient per layer, mm^-1
uniform sampler2D u_subsurface0;               // boundaries 0-3, 0..1 of u_depthScale
uniform sampler2D u_subsurface1;               // boundaries 4-7
uniform float u_depthScale;                    // mm per unit of the maps
uniform float u_uvPerMm;                       // texture units per mm along T and B
uniform float u_depthMax;                      // Depth_max of eq. 15, mm
uniform float u_tMaxCap;                       // -ln(threshold) / min sigma_t, mm (1e30 without)
uniform float u_threshold;                     // stop once exp(-tau_PM) falls below (0: never)
uniform float u_minCosView;                    // clamp of N_S . omega_out
uniform float u_ior;                           // relative index of the tissue; 1: no boundary

const float kPi = 3.14159265358979;

struct Frame {
  vec3 P, wo, Np, Ns, PS, T, B;
  vec2 uv;
  float tMax, cosDepth;
};

// PCG hash (Jarzynski and Olano 2020), as subsurface::pixelJitter.
uint pcgHash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}
float pixelJitter(uint x, uint y, uint seed) {
  return float(pcgHash(x + pcgHash(y + pcgHash(seed))) >> 8u) * (1.0 / 16777216.0);
}

// The cosine to the normal inside the tissue of a direction at cosine c outside (Snell's law).
float insideCosine(float c) {
  return u_ior > 1.0 ? sqrt(max(1.0 - (1.0 - c * c) / (u_ior * u_ior), 0.0)) : c;
}

// The direction inside the tissue, reversed, of light crossing the surface of normal N along -w
// (w unit, pointing out): Snell's law, as the truth refracts (Hanrahan and Krueger 1993 §4). The
// view path and the lights' paths refract alike; without a boundary, or from below the tangent
// plane (a light that the boundary's transmittance T(N.L) = 0 already removes), w itself.
vec3 insideDirection(vec3 w, vec3 N) {
  if (u_ior <= 1.0 || dot(w, N) <= 0.0) return w;
  return -refract(-w, N, 1.0 / u_ior);
}

float schlickPhase(float cosT, float k) {
  float denom = 1.0 - k * cosT;
  return (1.0 - k * k) / (4.0 * kPi * denom * denom);
}

// Boundary depths (mm) at uv, non-decreasing.
void sampleBoundaries(vec2 uv, out float b[8]) {
  vec4 a = texture(u_subsurface0, uv) * u_depthScale;
  vec4 c = u_boundaryCount > 4 ? texture(u_subsurface1, uv) * u_depthScale : vec4(1e30);
  b[0] = a.x; b[1] = max(a.y, b[0]); b[2] = max(a.z, b[1]); b[3] = max(a.w, b[2]);
  b[4] = max(c.x, b[3]); b[5] = max(c.y, b[4]); b[6] = max(c.z, b[5]); b[7] = max(c.w, b[6]);
}

int findLayer(float b[8], float depth) {
  int layer = 0;
  for (int i = 0; i < 8; ++i)
    if (i < u_boundaryCount && b[i] <= depth) layer = i + 1;
  return layer;
}

float thickness(float b[8], int i) {
  if (i >= u_boundaryCount) return 1e30;
  return b[i] - (i == 0 ? 0.0 : b[i - 1]);
}

vec2 uvAt(Frame f, vec3 X) {
  vec3 PX = X - f.P;  // projected into tangent space (François §2.1, Fig. 6)
  return f.uv + vec2(dot(PX, f.T), dot(PX, f.B)) * u_uvPerMm;
}

// exp(-tau_KM) for light arriving along -wi (wi unit, from M towards the light) at M, at distance
// t along the viewing ray (Algorithm 2, eq. 9-10; Norberg eq. 13-14 with the max(., 0) fix).
vec3 reducedIntensity(Frame f, float bM[8], vec3 M, float t, vec3 wi) {
  float w = f.tMax > 0.0 ? t / f.tMax : 0.0;
  vec3 NM = normalize((1.0 - w) * f.Np + w * f.Ns);  // eq. 9: tangent plane at P
  vec3 PM = (1.0 - w) * f.P + w * f.PS;
  float cosTheta = dot(NM, wi);
  if (cosTheta <= 1e-4) return vec3(0.0);
  float KM = abs(dot(M - PM, NM)) / cosTheta;  // eq. 10
  float bK[8];
  sampleBoundaries(uvAt(f, M + KM * wi), bK);
  vec3 tau = vec3(0.0);
  float above = 0.0;
  for (int i = 0; i < TISSUE_MAX_LAYERS; ++i) {
    if (i >= u_layerCount || above >= KM) break;
    float D = i < u_boundaryCount ? 0.5 * (thickness(bM, i) + thickness(bK, i)) : 1e30;
    float di = min(max(KM - above, 0.0), D / cosTheta);
    tau += di * u_sigmaT[i];
    above += D / cosTheta;
  }
  return exp(-tau);
}

Frame makeFrame(vec3 P, vec3 toEye, vec3 normal, vec4 tangent, vec4 plane, vec2 uv) {
  Frame f;
  f.P = P;
  f.wo = normalize(toEye);
  f.Np = normalize(normal);
  f.Ns = length(plane.xyz) > 1e-6 ? normalize(plane.xyz) : f.Np;
  f.PS = P + plane.w * f.Np;  // eq. 14
  vec3 T = tangent.xyz - f.Np * dot(f.Np, tangent.xyz);
  bool degenerate = length(T) < 1e-6;
  f.T = degenerate ? vec3(0.0) : normalize(T);
  f.B = degenerate ? vec3(0.0) : (tangent.w < 0.0 ? -1.0 : 1.0) * cross(f.Np, f.T);
  f.uv = uv;
  f.tMax = min(u_depthMax / max(dot(f.Ns, f.wo), u_minCosView), u_tMaxCap);  // eq. 15
  f.cosDepth = max(dot(f.Np, f.wo), 0.0);
  return f;
}

// Eq. 5 with n samples at t_i = (i + jitter) dt; returns the radiance (rgb) and samples used (a).
// lightWeight[l] scales light l's reduced intensity: the Fresnel transmittance of its entry
// (raymarch.frag; 1 for the CPU model, which has no boundary).
vec4 marchSingleScattering(Frame f, int n, float jitter, float lightWeight[MAX_LIGHTS]) {
  float dt = f.tMax / float(n);
  vec3 L = vec3(0.0), attenuation = vec3(1.0);
  int used = 0;
  for (int i = 0; i < TISSUE_MAX_SAMPLES; ++i) {
    if (i >= n) break;
    float t = (float(i) + jitter) * dt;
    vec3 M = f.P - t * f.wo;
    float bM[8];
    sampleBoundaries(uvAt(f, M), bM);
    int layer = min(findLayer(bM, t * f.cosDepth), u_layerCount - 1);
    attenuation *= exp(-u_sigmaT[layer] * (i == 0 ? jitter * dt : dt));
    for (int l = 0; l < MAX_LIGHTS; ++l) {
      if (l >= u_lightCount) break;
      vec3 wi = insideDirection(lightDirection(l, M), f.Np);
      float phase = schlickPhase(-dot(wi, f.wo), u_schlickK[layer]);
      vec3 Lri = lightWeight[l] * u_lightRadiance[l] * reducedIntensity(f, bM, M, t, wi);
      L += u_sigmaS[layer] * phase * Lri * attenuation * dt;
    }
    used = i + 1;
    if (u_threshold > 0.0 && max(attenuation.x, max(attenuation.y, attenuation.z)) < u_threshold) break;
  }
  return vec4(L, float(used));
}

// The multiple-scattered reflectance under the pixel (the diffusion term the march lacks:
// François et al. 2006 §4 leaves multiple scattering to future work; Norberg 2010 §1.1: it
// low-passes the light, §5.1: one colour per layer). Each layer i spanning depths [z_i, z_i+1]
// (the boundaries at the pixel) contributes its half-space albedo u_multipleAlbedo[i] in
// proportion to the share of the diffusely reflected light that visits it: in diffusion theory
// both the fluence and the chance to escape fall off as exp(-sigma_tr z), so the reflected light
// samples depth z with weight exp(-2 tau(z)), tau the sigma_tr-optical depth through the layers
// above. A homogeneous stack gives the one albedo exactly; the last layer takes what is left.
vec3 multipleScatteringAlbedo(float b[8]) {
  vec3 R = vec3(0.0), above = vec3(1.0);
  for (int i = 0; i < TISSUE_MAX_LAYERS; ++i) {
    if (i >= u_layerCount) break;
    if (i == u_layerCount - 1) {
      R += above * u_multipleAlbedo[i];
      break;
    }
    vec3 below = above * exp(-2.0 * u_sigmaTr[i] * thickness(b, i));
    R += (above - below) * u_multipleAlbedo[i];
    above = below;
  }
  return R;
}
