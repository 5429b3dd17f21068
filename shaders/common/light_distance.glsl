// Distance (mm) from a light to a point, as the shadow maps store it: a point light
// (light.w = 1, xyz = position mm) measures |P - position|; a directional light (w = 0,
// xyz = unit direction toward the light) measures along its travel direction, -dot(P, xyz).
float lightDistance(vec4 light, vec3 P) {
  return light.w > 0.5 ? length(P - light.xyz) : -dot(P, light.xyz);
}
