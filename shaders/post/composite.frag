#version 330 core
// HDR composite: the radiance target (lit objects, separable objects' specular) plus the
// blurred separable diffuse. Linear RGB; a = coverage.
uniform sampler2D u_radiance;
uniform sampler2D u_blurredDiffuse;
uniform ivec2 u_origin;  // pixels, the viewport's origin in the window
layout(location = 0) out vec4 o_color;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy) - u_origin;
  vec4 r = texelFetch(u_radiance, p, 0);
  o_color = vec4(r.rgb + texelFetch(u_blurredDiffuse, p, 0).rgb, r.a);
}
