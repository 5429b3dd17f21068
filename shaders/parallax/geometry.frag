#version 330 core
// Layered parallax multi-texturing (Oat 2006; Norberg 2010 §2.2, §3.2) into the HDR radiance
// target. Outer layer: base colour, normal map, opacity, lit directly (with shadows). Inner
// layers: looked up where the transmission vector reaches their depth (eq. 15-18, with Snell's
// law for the relative index), lit by the blurred texture-space lightmap (§2.2.2), their base
// blurred by the transmission distance (textureLod). Blend by (1 - opacity) N.V (eq. 19).
#include "common/surface.glsl"
#include "common/blinn_phong.glsl"
#include "common/lights.glsl"

#define MAX_LAYERS 3
uniform sampler2D u_lightmap;  // blurred, premultiplied by the visible fraction (a)
uniform sampler2D u_opacityMap;
uniform int u_hasOpacityMap;
uniform float u_opacity;       // without a map, 0..1
uniform sampler2D u_inner0, u_inner1, u_inner2;  // sRGB bases, shallowest first
uniform int u_layerCount;
uniform float u_layerDepthMm[MAX_LAYERS];
uniform float u_layerOpacity[MAX_LAYERS];
uniform float u_refractiveIndex;  // n_inside / n_outside
uniform float u_innerBlurPerMm;   // mm of blur radius per mm travelled
uniform float u_maxTransmissionMm;

vec3 innerBase(int i, vec2 uv, float lod) {
  if (i == 0) return srgbToLinear(textureLod(u_inner0, uv, lod).rgb);
  if (i == 1) return srgbToLinear(textureLod(u_inner1, uv, lod).rgb);
  return srgbToLinear(textureLod(u_inner2, uv, lod).rgb);
}

vec2 innerSize(int i) {
  if (i == 0) return vec2(textureSize(u_inner0, 0));
  if (i == 1) return vec2(textureSize(u_inner1, 0));
  return vec2(textureSize(u_inner2, 0));
}

// The blurred lightmap's irradiance (linear RGB) at uv, renormalised by its visible fraction.
// Where the offset leaves the chart (gutter: nothing drawn) or lands on a culled texel, the
// irradiance at the shading point's own texel stands in, else `fallback`.
vec3 lightmapIrradiance(vec2 uv, vec3 fallback) {
  vec4 e = texture(u_lightmap, uv);
  if (e.a > 1e-3) return e.rgb / e.a;
  e = texture(u_lightmap, v_uv);
  return e.a > 1e-3 ? e.rgb / e.a : fallback;
}

void main() {
  // Derivatives first (uniform control flow): the UV Jacobian, mm per UV unit. P and uv are
  // both affine over a triangle, so [dP/du dP/dv] = [dP/dx dP/dy] inverse([duv/dx duv/dy]).
  vec3 dPdx = dFdx(v_worldPosition), dPdy = dFdy(v_worldPosition);
  vec2 duvdx = dFdx(v_uv), duvdy = dFdy(v_uv);
  mat2 J = mat2(duvdx, duvdy);
  float det = determinant(J);
  mat2 Ji = abs(det) > 1e-20 ? inverse(J) : mat2(0.0);
  vec3 dPdu = dPdx * Ji[0][0] + dPdy * Ji[0][1];
  vec3 dPdv = dPdx * Ji[1][0] + dPdy * Ji[1][1];

  vec3 P = v_worldPosition;
  vec3 Ng = geometricNormal();
  vec3 N = surfaceNormal();
  vec3 V = normalize(u_cameraPosition - P);
  // The orthonormal tangent frame (as common/normal_mapping.glsl).
  vec3 T = v_tangent.xyz - Ng * dot(Ng, v_tangent.xyz);
  T = length(T) > 1e-6 ? normalize(T) : normalize(abs(Ng.x) < 0.9 ? cross(Ng, vec3(1, 0, 0)) : cross(Ng, vec3(0, 1, 0)));
  vec3 B = (v_tangent.w < 0.0 ? -1.0 : 1.0) * cross(Ng, T);
  vec3 Vt = vec3(dot(V, T), dot(V, B), dot(V, Ng));
  vec3 Nt = vec3(dot(N, T), dot(N, B), dot(N, Ng));
  // Eq. 15: R = -V - 2 (-V.N) N; eq. 16: T = (R_x, R_y, -R_z); Snell: tangential / n.
  vec3 R = reflect(-Vt, Nt);
  vec2 tangential = R.xy / max(u_refractiveIndex, 1.0);
  float Tz = max(sqrt(max(1.0 - dot(tangential, tangential), 0.0)), 1e-4);

  // The Gram matrix of the UV Jacobian turns a tangent-plane offset (mm) into UV units.
  float a = dot(dPdu, dPdu), b = dot(dPdu, dPdv), c = dot(dPdv, dPdv);
  float gramDet = a * c - b * b;
  float mmPerUv = 0.5 * (sqrt(a) + sqrt(c));
  float uvPerPixel = max(length(duvdx), length(duvdy));

  // The outer layer, lit directly; specular from every light through the normal map.
  vec3 albedo = surfaceAlbedo();
  vec3 outerIrradiance = u_ambient;
  vec3 specular = vec3(0.0);
  for (int i = 0; i < u_lightCount; ++i) {
    vec3 L = lightDirection(i, P);
    float shadow = shadowFactor(i, P, Ng);
    outerIrradiance += u_lightRadiance[i] * max(dot(N, L), 0.0) * shadow;
    specular += surfaceSpecular(N, L, V, u_specular, u_shininess) * u_lightRadiance[i] * shadow;
  }

  // Inner layers, deepest first, composited front over back by their opacities.
  vec3 inner = vec3(0.0);
  for (int i = u_layerCount - 1; i >= 0; --i) {
    float s = min(u_layerDepthMm[i] / Tz, u_maxTransmissionMm);  // eq. 17
    vec2 offsetMm = s * tangential;                              // eq. 18, mm along T, B
    vec3 o = offsetMm.x * T + offsetMm.y * B;
    vec2 duv = gramDet > 1e-12 ? vec2(c * dot(dPdu, o) - b * dot(dPdv, o), a * dot(dPdv, o) - b * dot(dPdu, o)) / gramDet
                               : vec2(0.0);
    vec2 uv = v_uv + duv;
    // Blur by the transmission distance (§2.2.2): a radius of u_innerBlurPerMm x s mm in texels
    // of this layer's base is the mip level; never sharper than the screen footprint.
    vec2 size = innerSize(i);
    float texelsBlur = u_innerBlurPerMm * s / max(mmPerUv, 1e-6) * size.x;
    float texelsScreen = uvPerPixel * size.x;
    float lod = log2(max(max(texelsBlur, texelsScreen), 1.0));
    vec3 layer = innerBase(i, uv, lod) * lightmapIrradiance(uv, outerIrradiance);
    float alpha = i == u_layerCount - 1 ? 1.0 : clamp(u_layerOpacity[i], 0.0, 1.0);
    inner = mix(inner, layer, alpha);
  }

  float opacity = u_hasOpacityMap == 1 ? texture(u_opacityMap, v_uv).r : u_opacity;
  // Eq. 19 and §2.2.3: s = see-through x N.V (saturate), x (1 - s) + y s.
  float see = (1.0 - clamp(opacity, 0.0, 1.0)) * clamp(dot(N, V), 0.0, 1.0);
  // The diffuse leaves through the boundary (common/specular.glsl boundaryWeight).
  vec3 color = mix(albedo * outerIrradiance, inner, see) * boundaryWeight(dot(Ng, V), u_specular) + specular;
  o_radiance = vec4(color, 1.0);
  o_diffuse = vec4(0.0, 0.0, 0.0, u_objectId);
  o_position = surfacePosition();
}
