// Texture-space diffusion: the light of the irradiance and final passes. One point light as in
// the lit pass (common/blinn_phong.glsl): irradiance = radiance * cos(theta) + ambient, so with
// no diffusion albedo * irradiance equals the lit pass's diffuse term.
uniform vec3 u_lightPosition;  // mm
uniform vec3 u_lightRadiance;  // linear RGB, colour * intensity
uniform vec3 u_ambient;        // linear RGB
uniform float u_specular;      // specular reflectance, 0..1
uniform float u_shininess;     // Blinn-Phong exponent

vec3 tsdIrradiance(vec3 position, vec3 N) {
  vec3 L = normalize(u_lightPosition - position);
  return u_lightRadiance * max(dot(N, L), 0.0) + u_ambient;
}

vec3 tsdSpecular(vec3 position, vec3 N, vec3 cameraPosition) {
  vec3 L = normalize(u_lightPosition - position);
  vec3 V = normalize(cameraPosition - position);
  float NdotL = max(dot(N, L), 0.0);
  if (NdotL <= 0.0) return vec3(0.0);
  float lobe = (u_shininess + 8.0) / (8.0 * 3.14159265) * pow(max(dot(N, normalize(L + V)), 0.0), u_shininess);
  return vec3(u_specular * lobe) * NdotL * 3.14159265 * u_lightRadiance;
}
