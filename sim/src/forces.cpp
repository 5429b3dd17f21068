#include "tissue/sim/forces.h"

#include <algorithm>

#include "gather.h"
#include "parallel.h"

namespace tissue::sim {
namespace detail {

void gatherPerVertex(const MassSpringSystem& system, std::span<const Vec3d> perSpring, std::span<Vec3d> out) {
  const SpringNetwork& springs = system.springs;
  parallelRanges(springs.vertexCount(), system.config.threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v) {
      Vec3d sum{};
      for (std::uint32_t k = springs.vertexSpringOffsets[v]; k < springs.vertexSpringOffsets[v + 1]; ++k) {
        const std::uint32_t e = springs.vertexSprings[k];
        if (springs.i[e] == v)
          sum += perSpring[e];
        else
          sum -= perSpring[e];
      }
      out[v] = sum;
    }
  });
}

}  // namespace detail

void springMatrixTimes(const MassSpringSystem& system, std::span<const Vec3d> x, std::span<const Vec3d> p,
                       double stiffnessWeight, double dampingWeight, std::span<Vec3d> out,
                       ForceScratch& scratch) {
  const SpringNetwork& s = system.springs;
  scratch.perSpring.resize(s.size());
  detail::parallelRanges(s.size(), system.config.threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t e = begin; e < end; ++e) {
      const Vec3d& xi = x[s.i[e]];
      const Vec3d& xj = x[s.j[e]];
      const Vec3d dp = p[s.i[e]] - p[s.j[e]];
      Vec3d q = springStiffnessTimes(xi, xj, s.restLength[e], stiffnessWeight * s.stiffness[e], dp);
      if (dampingWeight != 0.0 && s.damping[e] != 0.0) {
        const Vec3d d = xj - xi;
        const double len = length(d);
        if (len > 0.0) {
          const Vec3d n = (1.0 / len) * d;
          q += (dampingWeight * s.damping[e] * dot(n, dp)) * n;
        }
      }
      scratch.perSpring[e] = q;
    }
  });
  detail::gatherPerVertex(system, scratch.perSpring, out);
}

void computeForces(const MassSpringSystem& system, std::span<const Vec3d> x, std::span<const Vec3d> v,
                   std::span<Vec3d> forces, ForceScratch& scratch) {
  const SpringNetwork& s = system.springs;
  const SystemConfig& c = system.config;

  // Springs with their own damping, gathered per vertex.
  scratch.perSpring.resize(s.size());
  detail::parallelRanges(s.size(), c.threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t e = begin; e < end; ++e)
      scratch.perSpring[e] = springForce(x[s.i[e]], x[s.j[e]], v[s.i[e]], v[s.j[e]], s.restLength[e],
                                         s.stiffness[e], s.damping[e]);
  });
  detail::gatherPerVertex(system, scratch.perSpring, forces);

  // Gravity and Rayleigh mass damping: m (g - alpha v).
  detail::parallelRanges(forces.size(), c.threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k)
      forces[k] += system.masses[k] * (c.gravity - c.rayleighMass * v[k]);
  });

  // Rayleigh stiffness damping: -beta K v.
  if (c.rayleighStiffness != 0.0) {
    scratch.perVertex.resize(forces.size());
    springMatrixTimes(system, x, v, c.rayleighStiffness, 0.0, scratch.perVertex, scratch);
    detail::parallelRanges(forces.size(), c.threads, [&](std::size_t begin, std::size_t end) {
      for (std::size_t k = begin; k < end; ++k)
        forces[k] -= scratch.perVertex[k];
    });
  }
}

double kineticEnergy(const MassSpringSystem& system, std::span<const Vec3d> v) {
  double e = 0.0;
  for (std::size_t k = 0; k < v.size(); ++k)
    e += 0.5 * system.masses[k] * dot(v[k], v[k]);
  return e;
}

double elasticEnergy(const MassSpringSystem& system, std::span<const Vec3d> x) {
  const SpringNetwork& s = system.springs;
  double e = 0.0;
  for (std::size_t k = 0; k < s.size(); ++k) {
    const double stretch = length(x[s.j[k]] - x[s.i[k]]) - s.restLength[k];
    e += 0.5 * s.stiffness[k] * stretch * stretch;
  }
  return e;
}

double gravityEnergy(const MassSpringSystem& system, std::span<const Vec3d> x) {
  double e = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k)
    e -= system.masses[k] * dot(system.config.gravity, x[k]);
  return e;
}

Vec3d linearMomentum(const MassSpringSystem& system, std::span<const Vec3d> v) {
  Vec3d p{};
  for (std::size_t k = 0; k < v.size(); ++k)
    p += system.masses[k] * v[k];
  return p;
}

double maxStretch(const MassSpringSystem& system, std::span<const Vec3d> x) {
  const SpringNetwork& s = system.springs;
  double m = 0.0;
  for (std::size_t k = 0; k < s.size(); ++k) {
    const double ratio = length(x[s.j[k]] - x[s.i[k]]) / s.restLength[k];
    if (!(ratio <= m)) m = ratio;  // NaN propagates
  }
  return m;
}

}  // namespace tissue::sim
