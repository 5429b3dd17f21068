#version 330 core
// Texture-space diffusion, irradiance pass: diffuse irradiance E (linear RGB) and visibility.
#include "texture_space/light.glsl"

in vec3 v_worldPosition;
in vec3 v_normal;
in float v_eyeDot;

uniform int u_cull;          // 1: culled irradiance map (Jimenez §3)
uniform float u_cullCosine;  // cos(105 deg) = -0.2588 (§3, Listing 2)

layout(location = 0) out vec4 o_irradiance;  // rgb: E; a: 1 visible, 0 culled (or not drawn)
layout(location = 1) out vec4 o_stretch;     // r, g: |dP/du|, |dP/dv| in mm per UV unit; b, a: 1
layout(location = 2) out vec4 o_position;    // xyz: world position, mm; w: 1

uniform float u_mapSize;  // T, texels: the derivatives below are per texel of the T x T map

void main() {
  // Stretch correction (d'Eon et al. §3.2): screen-space derivatives in UV space are dP per
  // texel; times T they are mm per UV unit, independent of the map size, every frame.
  vec3 dPdu = dFdx(v_worldPosition) * u_mapSize, dPdv = dFdy(v_worldPosition) * u_mapSize;
  o_stretch = vec4(length(dPdu), length(dPdv), 1.0, 1.0);
  o_position = vec4(v_worldPosition, 1.0);
  if (u_cull == 1 && v_eyeDot < u_cullCosine) {  // Listing 2: occluded
    o_irradiance = vec4(0.0);
    return;
  }
  o_irradiance = vec4(tsdIrradiance(v_worldPosition, normalize(v_normal)), 1.0);
}
