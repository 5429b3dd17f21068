// Texture-space diffusion: the light of the irradiance and final passes. One point light as in
// the lit pass (common/blinn_phong.glsl): irradiance = radiance * cos(theta) + ambient, so with
// no diffusion albedo * irradiance equals the lit pass's diffuse term.
uniform vec3 u_lightPosition;  // mm
uniform vec3 u_lightRadiance;  // linear RGB, colour * intensity
uniform vec3 u_ambient;        // linear RGB

vec3 tsdIrradiance(vec3 position, vec3 N) {
  vec3 L = normalize(u_lightPosition - position);
  return u_lightRadiance * max(dot(N, L), 0.0) + u_ambient;
}
