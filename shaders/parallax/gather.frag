#version 330 core
// Layered parallax, lightmap: the texture-space irradiance of one light (IrradianceMap, rgb = E
// where visible, a = 1 visible / 0 culled or empty) box-filtered down by u_reduction into the
// reduced-resolution lightmap (Norberg §3.2: "render it into a texture with lower resolution").
// Lights after the first are added by blending (rgb only); the output stays premultiplied by
// the visible fraction a.
uniform sampler2D u_irradiance;  // T x T texels
uniform int u_reduction;         // texels of the irradiance map per lightmap texel, a side

out vec4 o_lightmap;

void main() {
  ivec2 base = ivec2(gl_FragCoord.xy) * u_reduction;
  vec4 sum = vec4(0.0);
  for (int y = 0; y < u_reduction; ++y)
    for (int x = 0; x < u_reduction; ++x)
      sum += texelFetch(u_irradiance, base + ivec2(x, y), 0);
  o_lightmap = sum / float(u_reduction * u_reduction);
}
