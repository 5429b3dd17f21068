#version 330 core
// HostDepth::TestAndWrite: the host's depth (blitted into a texture of its format, pixel
// coordinates of the host's framebuffer) into the renderer's depth buffer, so the geometry
// passes are depth-tested against what the host drew. Writes no colour (colour mask off).
uniform sampler2D u_hostDepth;  // window depth 0..1 as the host's passes wrote it
uniform ivec2 u_origin;         // pixels, the host viewport's origin
void main() { gl_FragDepth = texelFetch(u_hostDepth, ivec2(gl_FragCoord.xy) + u_origin, 0).r; }
