#version 330 core
// Texture-space diffusion in the render pipeline, irradiance pass: the scene's lights (all of
// them, common/lights.glsl, with their shadow maps and transmission through thin parts) lit
// exactly as the separable geometry pass lights its diffuse target (separable/geometry.frag),
// so the two methods diffuse the same light. The map holds albedo^p x E: p = 1 is pre-scatter
// texturing (what the separable method blurs), p = 0 post-scatter, 0.5 d'Eon et al.'s mix.
// Variant TISSUE_NORMAL_MAP: the normal map shades, through the mesh's tangent frames.
#include "common/normal_mapping.glsl"
#include "common/tonemap.glsl"
#include "common/lights.glsl"
#include "common/transmittance.glsl"

in vec3 v_worldPosition;
in vec3 v_normal;
in vec4 v_tangent;
in vec2 v_uv;
in float v_eyeDot;

uniform int u_cull;            // 1: culled irradiance map (Jimenez §3)
uniform float u_cullCosine;    // cos(105 deg) = -0.2588 (§3, Listing 2)
uniform float u_mapSize;       // T, texels
uniform sampler2D u_baseColor; // sRGB albedo
uniform sampler2D u_normalMap; // tangent-space normals
uniform float u_albedoPreScatter;  // p
uniform vec3 u_ambient;        // linear RGB irradiance added everywhere
uniform int u_twoSided;        // 1: a double-sided object, lit on the side the camera sees

layout(location = 0) out vec4 o_irradiance;  // rgb: albedo^p E; a: 1 visible, 0 culled (or not drawn)
layout(location = 1) out vec4 o_stretch;     // r, g: |dP/du|, |dP/dv| mm per UV unit; b: sqrt(|dP/du x dP/dv|) mm
layout(location = 2) out vec4 o_position;    // xyz: world position, mm; w: 1

void main() {
  // Stretch correction (d'Eon et al. §3.2), as texture_space/irradiance.frag.
  vec3 dPdu = dFdx(v_worldPosition) * u_mapSize, dPdv = dFdy(v_worldPosition) * u_mapSize;
  // b: sqrt of the area per UV unit^2 (mm; squared: mm^2, exact also for non-orthogonal axes;
  // the square root keeps it inside half-float range).
  o_stretch = vec4(length(dPdu), length(dPdv), sqrt(length(cross(dPdu, dPdv))), 1.0);
  o_position = vec4(v_worldPosition, 1.0);
  // Visibility also goes to depth (0 visible, 1 culled): the blur passes skip culled and empty
  // texels by an early depth test, which saves work where a shader branch would not.
  gl_FragDepth = 0.0;
  // A double-sided object: one of a texel's two sides always faces the camera, so nothing is
  // culled, and the texel is lit on the side seen (the final pass negates back-face normals too).
  bool back = u_twoSided == 1 && v_eyeDot < 0.0;
  if (u_cull == 1 && u_twoSided == 0 && v_eyeDot < u_cullCosine) {  // Listing 2: occluded
    o_irradiance = vec4(0.0);
    gl_FragDepth = 1.0;
    return;
  }
  vec3 Ng = normalize(v_normal);
  vec3 N = Ng;
#ifdef TISSUE_NORMAL_MAP
  N = perturbNormal(Ng, v_tangent, texture(u_normalMap, v_uv).xyz * 2.0 - 1.0);
#endif
  if (back) {  // as common/surface.glsl's surfaceNormal on a back face
    Ng = -Ng;
    N = -N;
  }
  vec3 E = u_ambient;
  for (int i = 0; i < u_lightCount; ++i) {
    vec3 L = lightDirection(i, v_worldPosition);
    E += u_lightRadiance[i] * shadowFactor(i, v_worldPosition, Ng) * max(dot(N, L), 0.0);
    E += transmittedLight(i, v_worldPosition, Ng, L);
  }
  vec3 albedo = srgbToLinear(texture(u_baseColor, v_uv).rgb);
  o_irradiance = vec4(E * pow(max(albedo, vec3(1e-6)), vec3(u_albedoPreScatter)), 1.0);  // pow(0, 0) is undefined
}
