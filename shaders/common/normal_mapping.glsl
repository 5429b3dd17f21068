// Tangent-space normal mapping: the TBN frame from the interpolated vertex normal N and
// tangent (T, w), with the bitangent B = w * cross(N, T) (the mesh module's convention,
// tissue/mesh/tangent_frames.h). T is re-orthogonalised against N (Gram-Schmidt) because
// interpolation breaks orthogonality.
vec3 perturbNormal(vec3 N, vec4 tangent, vec3 tangentNormal) {
  vec3 T = tangent.xyz - N * dot(N, tangent.xyz);
  float lengthT = length(T);
  if (lengthT < 1e-6) return N;  // degenerate frame (e.g. a UV pole): keep the vertex normal
  T /= lengthT;
  vec3 B = tangent.w * cross(N, T);
  return normalize(mat3(T, B, N) * tangentNormal);
}
