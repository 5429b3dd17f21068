// The fast mass-spring solver of Liu, Bargteil, O'Brien and Kavan, "Fast Simulation of
// Mass-Spring Systems", ACM Trans. Graph. 32(6), 2013 (SIGGRAPH Asia).
//
// The paper's text is not in ../shared/papers, so its equations are quoted here by content and
// by the name of the part that states them, not by number.
//
// Implicit Euler, x' = x + h v', v' = v + h M^-1 f(x'), is the critical point of
// g(x) = 1/2 (x - y)^T M (x - y) + h^2 E(x) with y = x + h v ("implicit Euler as energy
// minimisation"; external forces enter E as -x^T f_ext). A spring's energy is
// 1/2 k (|p1 - p2| - r)^2 = min over |d| = r of 1/2 k |(p1 - p2) - d|^2 (the spring-potential
// lemma), so with the directions d as extra unknowns the springs' energy is
// 1/2 x^T L x - x^T J d with L = sum k_i A_i A_i^T (x) I3 and J = sum k_i A_i S_i^T (x) I3
// (A_i the spring's incidence vector, S_i its selector). Block coordinate descent:
//   local step:  d_i = r_i (p1 - p2) / |p1 - p2|, each spring on its own;
//   global step: (M + h^2 L) x = M y + h^2 J d + h^2 f_ext, one solve with a matrix that does not
//                depend on the state, so it is factored once (sparse Cholesky) per (system, h).
// Each global step lowers g, so the method is stable for any h; with enough iterations it
// converges to the exact backward-Euler step.
//
// We solve for the displacement D = x' - x rather than x': A D = h M v + h^2 (J d - L x + f_ext)
// with A the same matrix. At rest every term of the right-hand side is exactly zero, so a
// system at rest stays at rest bit for bit, and rounding scales with the motion, not the
// coordinates. Damping (Rayleigh alpha M and beta K, spring damping c) is added implicitly as
// -C v' = -C D / h, which moves h C onto the matrix (see factor() below).
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>

#include "gather.h"
#include "parallel.h"
#include "tissue/core/stopwatch.h"
#include "tissue/sim/integrators.h"

namespace tissue::sim {

/// The factor and its key, plus the per-step scratch.
struct FastSolverCache::Impl {
  struct Key {
    double h = 0.0, alpha = 0.0, beta = 0.0;
    std::uint64_t fingerprint = 0;
    bool revision = false;  ///< `fingerprint` is the caller's system revision
    bool operator==(const Key&) const = default;
  };
  std::optional<Key> key;
  bool factored = false;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
  std::vector<std::int64_t> row;               ///< vertex -> row of the system, -1 when pinned
  std::vector<std::uint32_t> freeVertices;     ///< row -> vertex
  std::vector<std::uint32_t> pinnedCouplings;  ///< springs with exactly one pinned end
  std::vector<double> weight;                  ///< per spring: (h^2 + h beta) k + h c (g)
  std::vector<double> invD;                    ///< 1 / D of the LDL^T factor
  Eigen::MatrixX3d rhs, solution;
  std::vector<Vec3d> base, perSpring, perVertex, x0, work, previous;
};

FastSolverCache::FastSolverCache() = default;
FastSolverCache::~FastSolverCache() = default;
FastSolverCache::FastSolverCache(const FastSolverCache&) {}  // starts empty, fingerprinting
FastSolverCache& FastSolverCache::operator=(const FastSolverCache& other) {
  if (this != &other) m_impl.reset(), m_revision = 0;
  return *this;
}
FastSolverCache::FastSolverCache(FastSolverCache&&) noexcept = default;
FastSolverCache& FastSolverCache::operator=(FastSolverCache&&) noexcept = default;

FastSolverCache::Impl& FastSolverCache::impl() {
  if (!m_impl) m_impl = std::make_unique<Impl>();
  return *m_impl;
}

void FastSolverCache::clear() {
  m_impl.reset();
}

namespace {

/// A 64-bit fingerprint of everything the matrix depends on: the springs' end points,
/// stiffness and damping, the masses and which vertices are pinned. One pass over the arrays
/// (about one force pass of memory traffic), so an edited system is never solved with a stale
/// factor.
std::uint64_t systemFingerprint(const MassSpringSystem& s) {
  std::uint64_t hash = 0xcbf29ce484222325ull ^ s.vertexCount() ^ (std::uint64_t(s.springs.size()) << 32);
  auto mix = [&hash](std::uint64_t word) {
    hash ^= word + 0x9e3779b97f4a7c15ull + (hash << 6) + (hash >> 2);
  };
  for (std::size_t k = 0; k < s.vertexCount(); ++k)
    mix(std::bit_cast<std::uint64_t>(s.masses[k]) ^ (s.invMasses[k] == 0.0 ? 0x5bd1e995ull : 0ull));
  const SpringNetwork& n = s.springs;
  for (std::size_t e = 0; e < n.size(); ++e) {
    mix((std::uint64_t(n.i[e]) << 32) | n.j[e]);
    mix(std::bit_cast<std::uint64_t>(n.stiffness[e]));
    mix(std::bit_cast<std::uint64_t>(n.damping[e]));
  }
  return hash;
}

/// Builds and factors A = (1 + h alpha) M + (h^2 + h beta) L + h L_c over the free vertices.
/// The damping terms come from -C v' with v' = D / h on the left of the implicit-Euler
/// equation: Rayleigh mass damping alpha M exactly; Rayleigh stiffness damping beta K with K
/// replaced by L (K's axial part plus the full transverse stiffness, K <= L), and spring damping
/// c n n^T replaced by c I3 on the relative velocity; both keep A constant, hence prefactorable.
bool factor(const MassSpringSystem& system, double h, FastSolverCache::Impl& c) {
  const SpringNetwork& s = system.springs;
  const SystemConfig& config = system.config;
  const std::size_t n = system.vertexCount();
  c.row.assign(n, -1);
  c.freeVertices.clear();
  for (std::size_t v = 0; v < n; ++v)
    if (system.invMasses[v] != 0.0) {
      c.row[v] = static_cast<std::int64_t>(c.freeVertices.size());
      c.freeVertices.push_back(static_cast<std::uint32_t>(v));
    }
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(c.freeVertices.size() + 4 * s.size());
  for (std::uint32_t v : c.freeVertices)
    triplets.emplace_back(c.row[v], c.row[v], (1.0 + h * config.rayleighMass) * system.masses[v]);
  c.weight.resize(s.size());
  c.pinnedCouplings.clear();
  for (std::size_t e = 0; e < s.size(); ++e) {
    const double w = (h * h + h * config.rayleighStiffness) * s.stiffness[e] + h * s.damping[e];
    c.weight[e] = w;
    const std::int64_t ri = c.row[s.i[e]], rj = c.row[s.j[e]];
    if (ri >= 0) triplets.emplace_back(ri, ri, w);
    if (rj >= 0) triplets.emplace_back(rj, rj, w);
    if (ri >= 0 && rj >= 0) {
      triplets.emplace_back(ri, rj, -w);
      triplets.emplace_back(rj, ri, -w);
    } else if (ri >= 0 || rj >= 0) {
      c.pinnedCouplings.push_back(static_cast<std::uint32_t>(e));
    }
  }
  const auto rows = static_cast<Eigen::Index>(c.freeVertices.size());
  Eigen::SparseMatrix<double> a(rows, rows);
  a.setFromTriplets(triplets.begin(), triplets.end());
  c.ldlt.compute(a);
  c.rhs.resize(rows, 3);
  c.solution.resize(rows, 3);
  if (c.ldlt.info() != Eigen::Success) return false;
  const Eigen::VectorXd d = c.ldlt.vectorD();
  c.invD.resize(c.freeVertices.size());
  for (std::size_t r = 0; r < c.invD.size(); ++r)
    c.invD[r] = 1.0 / d(static_cast<Eigen::Index>(r));
  return true;
}

/// c.solution = A^-1 c.rhs with A = P^T L D L^T P, all three columns in one pass over L per
/// triangular solve. Eigen's sparse triangular solve runs column by column, reading L three
/// times, and the solve is bound by reading L (memory bandwidth) from about 10^4 springs up.
void solveThreeColumns(FastSolverCache::Impl& c) {
  const auto& l = c.ldlt.matrixL().nestedExpression();  // unit lower, column major
  const Eigen::Index n = c.rhs.rows();
  c.solution = c.ldlt.permutationP() * c.rhs;
  c.work.resize(static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i)
    c.work[i] = {c.solution(i, 0), c.solution(i, 1), c.solution(i, 2)};
  for (Eigen::Index j = 0; j < n; ++j) {  // L y = P b
    const Vec3d yj = c.work[j];
    for (Eigen::SparseMatrix<double>::InnerIterator it(l, j); it; ++it)
      if (it.row() > j) c.work[it.row()] -= it.value() * yj;
  }
  for (Eigen::Index j = 0; j < n; ++j)  // D z = y
    c.work[j] = c.invD[j] * c.work[j];
  for (Eigen::Index j = n - 1; j >= 0; --j) {  // L^T w = z
    Vec3d sum = c.work[j];
    for (Eigen::SparseMatrix<double>::InnerIterator it(l, j); it; ++it)
      if (it.row() > j) sum -= it.value() * c.work[it.row()];
    c.work[j] = sum;
  }
  for (Eigen::Index i = 0; i < n; ++i)
    c.rhs.row(i) << c.work[i].x, c.work[i].y, c.work[i].z;
  c.solution = c.ldlt.permutationPinv() * c.rhs;  // x = P^T w
}

/// The part of the right-hand side that does not change over the iterations, per free vertex:
/// h m v + h^2 m g, plus the coupling to pinned vertices that move (-A_fp D_p with D_p = h v_p).
void constantRightHandSide(const MassSpringSystem& system, const State& state, double h,
                           FastSolverCache::Impl& c) {
  c.base.resize(system.vertexCount());
  detail::parallelRanges(
      system.vertexCount(), system.config.threads, [&](std::size_t begin, std::size_t end) {
        for (std::size_t v = begin; v < end; ++v)
          c.base[v] = system.masses[v] * (h * state.v[v] + (h * h) * system.config.gravity);
      });
  const SpringNetwork& s = system.springs;
  for (std::uint32_t e : c.pinnedCouplings) {
    const bool iFree = c.row[s.i[e]] >= 0;
    const std::uint32_t freeEnd = iFree ? s.i[e] : s.j[e], pinnedEnd = iFree ? s.j[e] : s.i[e];
    c.base[freeEnd] += (c.weight[e] * h) * state.v[pinnedEnd];
  }
}

/// Local step at positions x (block coordinate descent, the d-step): per spring k (d - (x0_i - x0_j)) with
/// d = r (x_i - x_j) / |x_i - x_j|, gathered per vertex into J d - L x0. A spring of zero length
/// has no direction; it keeps the direction it had at the step's start (or none).
void localStep(const MassSpringSystem& system, std::span<const Vec3d> x, FastSolverCache::Impl& c) {
  const SpringNetwork& s = system.springs;
  c.perSpring.resize(s.size());
  detail::parallelRanges(s.size(), system.config.threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t e = begin; e < end; ++e) {
      const Vec3d start = c.x0[s.i[e]] - c.x0[s.j[e]];
      Vec3d now = x[s.i[e]] - x[s.j[e]];
      double len = length(now);
      if (!(len > 0.0)) now = start, len = length(start);
      const Vec3d d = len > 0.0 ? (s.restLength[e] / len) * now : Vec3d{};
      c.perSpring[e] = s.stiffness[e] * (d - start);
    }
  });
  c.perVertex.resize(system.vertexCount());
  detail::gatherPerVertex(system, c.perSpring, c.perVertex);
}

/// Whether the iterations should start from y = x + h v rather than from x. Block coordinate
/// descent only ever lowers the objective G(D) whose minimiser is the step (D = x' - x):
///   G(D) = 1/2 D^T ((1 + h alpha) M + h beta L + h L_c) D - h D^T M v + h^2 (E(x + D) - D^T f_ext),
/// so a fixed number of iterations ends no higher than where it started. The inertial
/// prediction (D = h v, Liu et al.'s choice) is the better start for smooth motion; at steps far
/// above the explicit limit, with rough velocities, it can stretch springs so far that a few
/// iterations end with more energy than the system had. Comparing G at both starts (D = 0 and
/// D = h v, one spring pass) keeps the better one. Pinned vertices move with h v in both.
bool startFromPrediction(const MassSpringSystem& system, const State& state, double h) {
  const SpringNetwork& s = system.springs;
  const SystemConfig& config = system.config;
  const int threads = config.threads;
  auto moved = [&](std::uint32_t v, bool predicted) {
    return predicted || system.invMasses[v] == 0.0 ? state.x[v] + h * state.v[v] : state.x[v];
  };
  auto springEnergy = [&](bool predicted) {
    return detail::parallelSum(s.size(), threads, [&](std::size_t e) {
      const double stretch = length(moved(s.i[e], predicted) - moved(s.j[e], predicted)) - s.restLength[e];
      return 0.5 * s.stiffness[e] * stretch * stretch;
    });
  };
  // Quadratic terms of G at D = h v over the free vertices: D^T L D and D^T L_c D per spring.
  auto isFree = [&](std::uint32_t v) { return system.invMasses[v] != 0.0 ? 1.0 : 0.0; };
  const double springQuadratic = detail::parallelSum(s.size(), threads, [&](std::size_t e) {
    const Vec3d dv = isFree(s.i[e]) * state.v[s.i[e]] - isFree(s.j[e]) * state.v[s.j[e]];
    return (config.rayleighStiffness * s.stiffness[e] + s.damping[e]) * dot(dv, dv);
  });
  const double massQuadratic = detail::parallelSum(system.vertexCount(), threads, [&](std::size_t v) {
    return isFree(static_cast<std::uint32_t>(v)) * system.masses[v] *
           ((0.5 * h * config.rayleighMass - 0.5) * dot(state.v[v], state.v[v]) -
            h * dot(state.v[v], config.gravity));
  });
  const double atPrediction = h * h * (massQuadratic + 0.5 * h * springQuadratic + springEnergy(true));
  const double atStart = h * h * springEnergy(false);
  return atPrediction <= atStart;
}

/// Global step (block coordinate descent, the x-step): A D = h M v + h^2 f_ext + h^2 (J d - L x0) - A_fp D_p,
/// x = x0 + D on the free vertices.
void globalStep(const MassSpringSystem& system, double h, FastSolverCache::Impl& c, std::span<Vec3d> x) {
  const double h2 = h * h;
  const std::size_t rows = c.freeVertices.size();
  detail::parallelRanges(rows, system.config.threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t r = begin; r < end; ++r) {
      const std::uint32_t v = c.freeVertices[r];
      const Vec3d b = c.base[v] + h2 * c.perVertex[v];
      c.rhs.row(static_cast<Eigen::Index>(r)) << b.x, b.y, b.z;
    }
  });
  solveThreeColumns(c);
  detail::parallelRanges(rows, system.config.threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t r = begin; r < end; ++r) {
      const auto i = static_cast<Eigen::Index>(r);
      x[c.freeVertices[r]] =
          c.x0[c.freeVertices[r]] + Vec3d{c.solution(i, 0), c.solution(i, 1), c.solution(i, 2)};
    }
  });
}

}  // namespace

StepStats stepFastMassSpring(const MassSpringSystem& system, State& state, double h, StepWorkspace& ws,
                             const ImplicitSolverConfig& solver) {
  StepStats stats;
  FastSolverCache::Impl& c = ws.fast.impl();
  const SystemConfig& config = system.config;

  // Prefactor once per (system, h): the matrix does not depend on the state.
  const std::uint64_t revision = ws.fast.systemRevision();
  const FastSolverCache::Impl::Key key{h, config.rayleighMass, config.rayleighStiffness,
                                       revision != 0 ? revision : systemFingerprint(system), revision != 0};
  if (!c.key || *c.key != key) {
    Stopwatch clock;
    c.factored = factor(system, h, c);
    c.key = key;
    stats.refactored = true;
    stats.factorMs = clock.elapsedMs();
  }
  // A is symmetric positive definite whenever masses > 0 and k, c, alpha, beta >= 0; should
  // the factorisation still fail (negative coefficients), take a linearised implicit step.
  if (!c.factored) return stepImplicitEuler(system, state, h, ws, solver);

  // Start from the inertial prediction y = x + h v or from x itself, whichever has the lower
  // objective; pinned vertices move with their velocity either way.
  const std::size_t n = system.vertexCount();
  c.x0 = state.x;
  const bool fromPrediction = startFromPrediction(system, state, h);
  detail::parallelRanges(n, config.threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v)
      state.x[v] = c.x0[v] + (fromPrediction || system.invMasses[v] == 0.0 ? h : 0.0) * state.v[v];
  });
  constantRightHandSide(system, state, h, c);

  // Fixed iterations, or fewer once converged: an iteration that moves no free vertex by more
  // than localGlobalTolerance times the step's largest displacement is the last (at small h the
  // inertial prediction is nearly the answer and one or two suffice).
  const std::size_t rows0 = c.freeVertices.size();
  const double tol2 = solver.localGlobalTolerance * solver.localGlobalTolerance;
  for (int it = 0; it < std::max(1, solver.localGlobalIterations); ++it) {
    c.previous.resize(rows0);
    for (std::size_t r = 0; r < rows0 && tol2 > 0.0; ++r)
      c.previous[r] = state.x[c.freeVertices[r]];
    localStep(system, state.x, c);
    globalStep(system, h, c, state.x);
    stats.localGlobalIterations = it + 1;
    if (tol2 == 0.0) continue;
    double change = 0.0, scale = 0.0;
    for (std::size_t r = 0; r < rows0; ++r) {
      const std::uint32_t v = c.freeVertices[r];
      const Vec3d moved = state.x[v] - c.previous[r], step = state.x[v] - c.x0[v];
      change = std::max(change, dot(moved, moved));
      scale = std::max(scale, dot(step, step));
    }
    if (change < tol2 * scale) break;
  }

  const auto rows = c.freeVertices.size();
  // v(t+h) = (x(t+h) - x(t)) / h; pinned vertices keep their velocity.
  const double invH = 1.0 / h;
  detail::parallelRanges(rows, config.threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t r = begin; r < end; ++r) {
      const std::uint32_t v = c.freeVertices[r];
      state.v[v] = invH * (state.x[v] - c.x0[v]);
    }
  });
  return stats;
}

}  // namespace tissue::sim
