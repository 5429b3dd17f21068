#version 330 core
// Lit surface, fragment stage: base colour texture, tangent-space normal map, Blinn-Phong
// from one point light, then exposure, tone map and sRGB encoding.
// Variants: TISSUE_NORMAL_MAP (sample the normal map through the TBN frame; else the
// interpolated vertex normal is used).

#include "common/normal_mapping.glsl"
#include "common/blinn_phong.glsl"
#include "common/tonemap.glsl"

in vec3 v_worldPosition;
in vec3 v_normal;
in vec4 v_tangent;
in vec2 v_uv;

uniform sampler2D u_baseColor;  // sRGB-encoded RGBA8
uniform sampler2D u_normalMap;  // tangent-space normals, RGB = n * 0.5 + 0.5
uniform vec3 u_cameraPosition;  // mm
uniform vec3 u_lightPosition;   // mm
uniform vec3 u_lightRadiance;   // linear RGB, colour * intensity
uniform vec3 u_ambient;         // linear RGB
uniform float u_specular;       // specular reflectance, 0..1
uniform float u_shininess;      // Blinn-Phong exponent
uniform float u_exposure;       // multiplies the radiance before the tone map

layout(location = 0) out vec4 o_color;

void main() {
  vec3 N = normalize(v_normal);
#ifdef TISSUE_NORMAL_MAP
  vec3 tangentNormal = texture(u_normalMap, v_uv).xyz * 2.0 - 1.0;
  N = perturbNormal(N, v_tangent, tangentNormal);
#endif
  vec3 albedo = srgbToLinear(texture(u_baseColor, v_uv).rgb);
  vec3 L = normalize(u_lightPosition - v_worldPosition);
  vec3 V = normalize(u_cameraPosition - v_worldPosition);
  vec3 color = u_ambient * albedo + blinnPhong(N, L, V, albedo, u_specular, u_shininess) * u_lightRadiance;
  o_color = vec4(linearToSrgb(tonemapReinhard(color * u_exposure)), 1.0);
}
