// Output transform: Reinhard's x / (1 + x) tone map (Reinhard et al. 2002, eq. 3) per
// channel, then the sRGB transfer function (IEC 61966-2-1), and its inverse for textures.
vec3 tonemapReinhard(vec3 c) { return c / (1.0 + c); }

vec3 linearToSrgb(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

vec3 srgbToLinear(vec3 c) {
  return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), step(vec3(0.04045), c));
}
