// The scene's lights (at most MAX_LIGHTS) and their shadow maps: 3x3 percentage-closer
// filtering (Reeves et al. 1987) over the light-distance maps of shaders/shadow/.
#include "common/light_distance.glsl"
#define MAX_LIGHTS 4

uniform int u_lightCount;
uniform vec4 u_lightVector[MAX_LIGHTS];       // xyz position mm (w = 1) or unit direction toward the light (w = 0)
uniform vec3 u_lightRadiance[MAX_LIGHTS];     // linear RGB, colour * intensity
uniform int u_lightShadowLayer[MAX_LIGHTS];   // layer of u_shadowMaps, -1 = no shadow
uniform mat4 u_lightShadowMatrix[MAX_LIGHTS]; // world (mm) to the shadow map's clip space
uniform float u_lightBiasMm[MAX_LIGHTS];      // mm, normal offset before the lookup
uniform vec2 u_lightTexelMm[MAX_LIGHTS];      // a map texel's width, mm = x + y * light distance mm
uniform sampler2DArray u_shadowMaps;          // R32F light distances, mm

// Unit vector from P toward light i.
vec3 lightDirection(int i, vec3 P) {
  vec4 l = u_lightVector[i];
  return l.w > 0.5 ? normalize(l.xyz - P) : l.xyz;
}

// Shadow map coordinates (xy in 0..1) of P for light i; z < 0 when behind the light.
vec3 shadowCoordinates(int i, vec3 P) {
  vec4 c = u_lightShadowMatrix[i] * vec4(P, 1.0);
  return vec3(c.xy / c.w * 0.5 + 0.5, c.w);
}

// Fraction of light i reaching P (1 = lit), 3x3 PCF. The point is pushed out along N by the
// bias plus two texels of the map at P (normal-offset shadows, Holbert 2011), and the depths
// compared with the same margin: a texel covers a patch of surface whose depth spans about its
// width at 45 degrees, and the 3x3 kernel reaches one texel further, so a bias fixed in mm would
// shadow the surface that the map stores wherever a texel is wider than the bias.
float shadowFactor(int i, vec3 P, vec3 N) {
  int layer = u_lightShadowLayer[i];
  if (layer < 0) return 1.0;
  vec2 t = u_lightTexelMm[i];
  float bias = u_lightBiasMm[i] + 2.0 * (t.x + t.y * lightDistance(u_lightVector[i], P));
  vec3 Pb = P + N * bias;
  vec3 c = shadowCoordinates(i, Pb);
  if (c.z <= 0.0 || any(lessThan(c.xy, vec2(0.0))) || any(greaterThan(c.xy, vec2(1.0)))) return 1.0;
  float d = lightDistance(u_lightVector[i], Pb);
  vec2 texel = 1.0 / vec2(textureSize(u_shadowMaps, 0).xy);
  float lit = 0.0;
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x)
      lit += d <= texture(u_shadowMaps, vec3(c.xy + vec2(x, y) * texel, float(layer))).r + bias ? 1.0 : 0.0;
  return lit / 9.0;
}

// Distance (mm) light i travels inside the object before reaching P (0 when nothing is in
// front of P, or without a shadow map): the shadow map's nearest distance subtracted from P's.
// The nearest over the 3x3 texels around P (the PCF's footprint): near the object's outline as
// the light sees it, a point on the far side projects up to a texel outside the texels the
// rasteriser covered, and a single lookup there reads "nothing in front" (thickness 0, full
// transmittance) and lights the dark side in streaks along the map's texel columns.
float thicknessMm(int i, vec3 P) {
  int layer = u_lightShadowLayer[i];
  if (layer < 0) return 0.0;
  vec3 c = shadowCoordinates(i, P);
  if (c.z <= 0.0 || any(lessThan(c.xy, vec2(0.0))) || any(greaterThan(c.xy, vec2(1.0)))) return 0.0;
  vec2 texel = 1.0 / vec2(textureSize(u_shadowMaps, 0).xy);
  float nearest = 3.0e38;  // the loop's centre tap is P's own texel
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x)
      nearest = min(nearest, texture(u_shadowMaps, vec3(c.xy + vec2(x, y) * texel, float(layer))).r);
  return max(lightDistance(u_lightVector[i], P) - nearest, 0.0);
}
