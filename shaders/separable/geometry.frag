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
#include "common/transmittance.glsl"

void main() {
  vec3 N = surfaceNormal();
  vec3 Ng = geometricNormal();
  vec3 albedo = surfaceAlbedo();
  vec3 V = normalize(u_cameraPosition - v_worldPosition);
  vec3 diffuse = u_ambient * albedo;
  vec3 specular = vec3(0.0);
  for (int i = 0; i < u_lightCount; ++i) {
    vec3 L = lightDirection(i, v_worldPosition);
    vec3 E = u_lightRadiance[i] * shadowFactor(i, v_worldPosition, Ng);
    diffuse += lambertDiffuse(N, L, albedo) * E;
    specular += surfaceSpecular(N, L, V, u_specular, u_shininess) * E;
    diffuse += transmittedLight(i, v_worldPosition, Ng, L) * albedo;
  }
  // The light leaves through the boundary (common/specular.glsl boundaryWeight) at the pixel it
  // entered: the blur radius (mm) is far below the surface's radius of curvature.
  diffuse *= boundaryWeight(dot(Ng, V), u_specular);  // Ng: as lit/lit.frag
  o_radiance = vec4(specular, 1.0);
  o_diffuse = vec4(diffuse, u_objectId);
  o_position = surfacePosition();
}
