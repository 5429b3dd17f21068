// The object's model transform (SceneObject::model), for the vertex stages: positions by
// u_model, normals and the local planes' normals by the normal matrix (M3^-1)^T computed on
// the CPU, tangents by M3 (surface vectors stay tangent to the transformed surface).
uniform mat4 u_model;         // object (mm) to world (mm)
uniform mat3 u_normalMatrix;  // (M3^-1)^T

// normalize() that leaves a zero vector (a degenerate tangent, an absent plane) zero, not NaN.
vec3 modelSafeNormalize(vec3 v) {
  float l = length(v);
  return l > 0.0 ? v / l : v;
}

vec3 modelPosition(vec3 p) { return (u_model * vec4(p, 1.0)).xyz; }
vec3 modelNormal(vec3 n) { return modelSafeNormalize(u_normalMatrix * n); }
vec4 modelTangent(vec4 t) { return vec4(modelSafeNormalize(mat3(u_model) * t.xyz), t.w); }

// A local plane (N_S, d mm) of subsurface texture mapping (François eq. 14: P_S = P + d N_p)
// at a vertex of normal n (object space). N_S is a normal; d is chosen so that the plane through
// P_S with normal N_S maps onto its image: N_S'.(P' + d' N_p' - M P_S) = 0, i.e.
// d' = d (N_S' . M3 N_p) / (N_S' . N_p'), which is s d for a rotation and uniform scale s.
vec4 modelPlane(vec4 plane, vec3 n) {
  vec3 Ns = modelSafeNormalize(u_normalMatrix * plane.xyz);
  vec3 Mn = mat3(u_model) * n;
  vec3 Np = modelSafeNormalize(u_normalMatrix * n);
  float denominator = dot(Ns, Np);
  float d = abs(denominator) > 1e-3 ? plane.w * dot(Ns, Mn) / denominator : plane.w * length(Mn);
  return vec4(Ns, d);
}
