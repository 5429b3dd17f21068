// Surface fragment inputs shared by the shading methods (common/surface.vert's outputs), the
// object's textures and material, and the G-buffer outputs every method writes:
//   0 radiance (linear HDR RGB; a = 1 where covered), 1 diffuse before the separable blur
//   (RGB; a = object id), 2 world position (mm) and view depth (mm).
// Variants: TISSUE_NORMAL_MAP (sample the normal map through the TBN frame).
#include "common/normal_mapping.glsl"
#include "common/tonemap.glsl"

in vec3 v_worldPosition;
in vec3 v_normal;
in vec4 v_tangent;
in vec2 v_uv;
in vec4 v_plane;

uniform sampler2D u_baseColor;  // sRGB-encoded RGBA8
uniform sampler2D u_normalMap;  // tangent-space normals, RGB = n * 0.5 + 0.5
uniform vec3 u_cameraPosition;  // mm
uniform vec3 u_cameraForward;   // unit view direction
uniform vec3 u_ambient;         // linear RGB
uniform float u_specular;       // specular reflectance, 0..1
uniform float u_shininess;      // Blinn-Phong exponent
uniform float u_objectId;       // 1.. within the frame (an integer stored as float)

layout(location = 0) out vec4 o_radiance;
layout(location = 1) out vec4 o_diffuse;
layout(location = 2) out vec4 o_position;

// The interpolated vertex normal, on the side the camera sees: a back face (drawn only for a
// double-sided object, render::SceneObject::doubleSided) shades with the normal negated.
vec3 geometricNormal() { return gl_FrontFacing ? normalize(v_normal) : -normalize(v_normal); }

// The shading normal: the normal map through the TBN frame, or the interpolated vertex normal.
// On a back face the whole perturbed normal is negated: the back of a displaced sheet, whose
// bumps are the front's dents (flipping only N in the TBN frame would mirror the bumps instead).
vec3 surfaceNormal() {
  vec3 N = normalize(v_normal);
#ifdef TISSUE_NORMAL_MAP
  vec3 tangentNormal = texture(u_normalMap, v_uv).xyz * 2.0 - 1.0;
  N = perturbNormal(N, v_tangent, tangentNormal);
#endif
  return gl_FrontFacing ? N : -N;
}

vec3 surfaceAlbedo() { return srgbToLinear(texture(u_baseColor, v_uv).rgb); }

// World position (mm) and view depth (mm along the camera's forward axis).
vec4 surfacePosition() {
  return vec4(v_worldPosition, dot(v_worldPosition - u_cameraPosition, u_cameraForward));
}
