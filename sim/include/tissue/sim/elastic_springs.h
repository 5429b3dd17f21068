#pragma once
/// \file
/// Spring stiffness from material constants: a Young's modulus E (kPa), a Poisson's ratio and a
/// density become the stiffness (N/mm) of every spring of a network, one formula per network type
/// (tet edges, the embedded lattice, a surface shell). See docs/DECISIONS.md ("Springs from
/// material constants") for the choices and docs/RESULTS.md for the measured moduli.
///
/// A network of central springs has a fixed effective Poisson's ratio: for an isotropic network
/// the Cauchy relation C12 = C44 holds, so lambda = mu and nu = 1/4 (kEffectivePoissonRatio). The
/// configured ratio is validated and reported, but it does not change the springs (a
/// volume-preserving term is a later step).

#include <span>

#include "tissue/core/result.h"
#include "tissue/core/types.h"
#include "tissue/sim/lattice.h"
#include "tissue/sim/spring_network.h"
#include "tissue/sim/vec3.h"

namespace tissue::sim {

/// An isotropic linear-elastic material.
struct ElasticMaterial {
  double youngsModulusKpa = 5.0;    ///< E in kPa (1 kPa = 1e-3 N/mm^2); liver about 4-6 kPa
  double poissonRatio = 0.25;       ///< nu, dimensionless, in (0, 0.5); the springs realise 1/4
  double densityGPerMm3 = 1.06e-3;  ///< g/mm^3 (liver 1.06 g/cm^3 = 1.06e-3 g/mm^3)
};

/// Effective Poisson's ratio of the isotropic central-force networks built here (Cauchy relation
/// lambda = mu, so nu = lambda / (2 (lambda + mu)) = 1/4).
inline constexpr double kEffectivePoissonRatio = 0.25;

/// kPa -> N/mm^2 (1 kPa = 1e3 N/m^2 = 1e-3 N/mm^2).
constexpr double kpaToNewtonPerMm2(double kpa) {
  return kpa * 1.0e-3;
}

/// Checks the material; the Error names the key: "youngs_modulus_kpa: expected a positive number
/// (kPa), got -3", "poisson_ratio: expected a number in (0, 0.5) ...", "density_g_per_mm3: ...".
Result<void> validateMaterial(const ElasticMaterial& material);

/// Which per-tet formula gives the tet-edge springs.
enum class TetStiffnessFormula {
  /// Lloyd, Szekely & Harders 2007 ("Identification of spring parameters for deformable object
  /// simulation", IEEE TVCG 13(5)): the regular tet of edge l has k = (2 sqrt 2 / 25) E l on
  /// each edge; a tet of volume V uses the regular tet of equal volume, l = (6 sqrt 2 V)^(1/3).
  Lloyd2007,
  /// Van Gelder 1998 ("Approximate simulation of elastic membranes by triangulated spring
  /// meshes", J. Graphics Tools 3(2)), 3D analogue: k_e += E V_t / l_e^2 for each tet t of e.
  VanGelder1998,
  /// Lloyd's equal stiffness on the 6 edges of a tet, its value fixed by the isotropic projection
  /// of the tet's spring tensor instead of the regular tet of equal volume: for springs,
  /// sum_iikk C_iikk = (1/V) sum_e k_e l_e^2 and the isotropic part (lambda = mu) has
  /// mu = sum_iikk C_iikk / 15, so mu = 2E/5 needs sum_e k_e l_e^2 = 6 E V_t, i.e.
  /// k = 6 E V_t / sum_e l_e^2 (Van Gelder's form meets the same identity edge by edge). On a
  /// regular tet k = E l / (6 sqrt 2) = 0.118 E l, within 4% of Lloyd's 0.113 E l; unlike it, it
  /// stays right for the right-angled tets of a split cube (docs/RESULTS.md, the uniaxial test).
  LloydIsotropicProjection,
};

/// Sets the stiffness of every spring of `network` (one per unique tet edge, as
/// buildTetEdgeSprings makes it) by summing `formula` over the tets that hold the edge; E from
/// `material`. Positions in mm, #vertices. Fails on a bad material, a tet of non-positive volume,
/// a tet edge without a spring, or a spring that is no tet edge.
Result<void> setTetEdgeStiffness(SpringNetwork& network, std::span<const Vec3d> positions,
                                 std::span<const Tet> tets, const ElasticMaterial& material,
                                 TetStiffnessFormula formula = TetStiffnessFormula::LloydIsotropicProjection);

/// How the lattice's springs on the boundary are treated.
enum class LatticeBoundary {
  /// Assembled cell by cell (as finite elements): each cell adds its share to its 28 springs, so
  /// an edge on a flat face (2 cells) gets half the interior value and a face diagonal on the
  /// surface (1 cell) half. Every cell then has exactly the target elastic tensor.
  PerCell,
  /// Every spring gets the interior value (as if shared by the full number of cells): the
  /// surface layer is too stiff. For the comparison in the tests and docs only.
  InteriorValue,
};

/// Stiffness (N/mm) of the lattice's springs in the interior of a cubic lattice of spacing
/// `cellSizeMm` (mm) for Young's modulus E (kPa), with nu = 1/4 and mu = 2E/5. For the
/// central-force simple-cubic lattice, C_ijkl = (1/a^3) sum_(springs per node) k L^2 n_i n_j n_k n_l
/// gives C11 = (k1 + 2 k2 + 4 k3 / 3) / a, C12 = C44 = (k2 + 4 k3 / 3) / a; isotropy
/// (C11 - C12 = 2 C44) needs k1 = k2 + 8 k3 / 3. The member chosen is k3 = 0, k1 = k2 = mu a.
struct LatticeSpringStiffness {
  double edge = 0.0;          ///< k1, N/mm, springs along cell edges (length a)
  double faceDiagonal = 0.0;  ///< k2, N/mm, face diagonals (a sqrt 2)
  double bodyDiagonal = 0.0;  ///< k3, N/mm, body diagonals (a sqrt 3)
};
/// The interior stiffness of the chosen member of the isotropic family (see above).
LatticeSpringStiffness latticeInteriorStiffness(double youngsModulusKpa, double cellSizeMm);

/// Sets the stiffness of every spring of `lattice` from `material` (E only; nu = 1/4 is the
/// lattice's own), assembled per `boundary`. Fails on a bad material or a lattice whose springs
/// are not the 28 corner pairs of its cells.
Result<void> setLatticeStiffness(EmbeddedLattice& lattice, const ElasticMaterial& material,
                                 LatticeBoundary boundary = LatticeBoundary::PerCell);

/// Settings of a shell (surface and bending springs).
struct ShellConfig {
  double thicknessMm = 2.0;      ///< t, mm, the membrane's thickness
  double bendingFraction = 0.1;  ///< bending spring k = this times the membrane k of its shared edge
};

/// Sets the stiffness of the springs of a surface network (edge springs, and bending springs
/// between the opposite vertices of edges shared by two triangles, as buildSurfaceSprings makes
/// them): Van Gelder 1998's membrane form k_e = E t sum_(T holding e) A_T / l_e^2, and each
/// bending spring `shell.bendingFraction` times its edge's k. A shell is not a volume: it
/// resists stretching of the surface and (weakly) bending, not compression of what it encloses.
/// Positions in mm. Fails on a bad material or thickness, degenerate triangles, or a spring
/// that is neither an edge nor a bending spring.
Result<void> setSurfaceStiffness(SpringNetwork& network, std::span<const Vec3d> positions,
                                 std::span<const Triangle> triangles, const ElasticMaterial& material,
                                 const ShellConfig& shell = {});

}  // namespace tissue::sim
