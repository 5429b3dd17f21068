#version 330 core
// Layered parallax, one pass of the lightmap blur: the mean of a Poisson disc of samples
// (Norberg §2.2.2; Cook 1985), radius in mm on the surface turned into UV units per axis by the
// irradiance pass's stretch map (mm per UV unit). Several passes of a smaller disc replace one
// large one (§3.2). The map is premultiplied by the visible fraction a, so empty (gutter) and
// culled texels add nothing and the sum is renormalised by the gathered a when it is read.
#define MAX_DISC 32
uniform sampler2D u_input;    // lightmap, premultiplied (rgb E a, a)
uniform sampler2D u_stretch;  // rg: |dP/du|, |dP/dv|, mm per UV unit
uniform vec2 u_disc[MAX_DISC];  // unit-disc offsets, mean 0
uniform int u_discCount;
uniform float u_radiusMm;     // mm on the surface, this pass
uniform float u_size;         // lightmap texels a side

out vec4 o_lightmap;

void main() {
  vec2 uv = gl_FragCoord.xy / u_size;
  vec2 mmPerUv = max(texture(u_stretch, uv).rg, vec2(1e-3));
  vec2 radiusUv = u_radiusMm / mmPerUv;
  vec4 sum = vec4(0.0);
  for (int i = 0; i < u_discCount; ++i)
    sum += texture(u_input, uv + u_disc[i] * radiusUv);
  o_lightmap = sum / float(u_discCount);
}
