#pragma once
/// \file
/// Validation of springs from material constants (elastic_springs.h): a block meshed as the
/// embedded lattice or as tets of the same cubic grid, under uniaxial compression (the effective
/// Young's modulus) and under a rigid sphere (Hertz indentation).
///
/// Method: the geometrically linear network, i.e. the stiffness matrix at rest
/// K = sum_springs k n n^T (the tangent of the spring forces at L = L0), with constraints per
/// degree of freedom (rollers: one axis held, the others free), solved by a sparse Cholesky
/// factorisation. solveStatic pins whole vertices, which cannot express rollers, and Hertz theory
/// is itself small-strain linear elasticity. solveLinearStatic agrees with solveStatic on the
/// nonlinear springs to O(strain) (tests/sim/elastic_springs_test.cpp).

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/types.h"
#include "tissue/sim/elastic_springs.h"
#include "tissue/sim/spring_network.h"
#include "tissue/sim/vec3.h"

namespace tissue::sim {

/// Which network meshes the block.
enum class ElasticNetwork {
  Lattice,  ///< buildEmbeddedLattice of the box, setLatticeStiffness
  Tets,     ///< the same grid's cubes split into tets, buildTetEdgeSprings, setTetEdgeStiffness
};

/// How each cube of the grid is split into tets.
enum class CubeSplit {
  Five,  ///< 4 corner tets and a central regular one, mirrored in alternate cubes (conforming)
  Six,   ///< Kuhn / Freudenthal: 6 tets around the cube's (+1,+1,+1) diagonal
};

/// One held degree of freedom: vertex `vertex` moves by `displacementMm` along `axis` (0 x, 1 y,
/// 2 z); the other axes of the vertex stay free unless constrained too.
struct DofConstraint {
  std::uint32_t vertex = 0;
  int axis = 2;
  double displacementMm = 0.0;  ///< mm
};

/// The linear static solution.
struct LinearStaticResult {
  std::vector<Vec3d> displacement;  ///< mm, #vertices
  std::vector<double> reactionN;    ///< N, per constraint: the force the support applies along its axis
};

/// Solves K u = 0 on the free degrees of freedom with `constraints` prescribed (K the network's
/// stiffness matrix at the rest positions `rest`, mm). Fails on a constraint out of range, a
/// degree of freedom held twice, or a singular system (too few constraints: a rigid motion left).
/// `vertexOrder`: the elimination order of the vertices (a permutation, e.g. nested dissection of
/// a grid: gridEliminationOrder); empty: a minimum-degree order.
Result<LinearStaticResult> solveLinearStatic(const SpringNetwork& network, std::span<const Vec3d> rest,
                                             std::span<const DofConstraint> constraints,
                                             std::span<const std::uint32_t> vertexOrder = {});

/// A nested-dissection elimination order of the nodes of a grid of `cells` cells (numbered
/// i + (nx+1)(j + (ny+1) k)): much less fill than minimum degree on a 3D grid (George 1973).
std::vector<std::uint32_t> gridEliminationOrder(std::array<int, 3> cells);

/// The tets of the grid of `cells` cubes (x, y, z) over nodes numbered i + (nx+1) (j + (ny+1) k),
/// positively oriented.
std::vector<Tet> gridTets(std::array<int, 3> cells, CubeSplit split = CubeSplit::Five);

/// A block [0, cells.x h] x [0, cells.y h] x [0, cells.z h] (mm) as a spring network.
struct ElasticBlock {
  std::vector<Vec3d> positions;  ///< mm, grid order: i + (nx+1) (j + (ny+1) k)
  SpringNetwork springs;         ///< stiffness from the material (N/mm, stored as g/s^2)
  std::array<int, 3> cells{};
  double cellSizeMm = 0.0;
  std::size_t node(int i, int j, int k) const {
    return static_cast<std::size_t>(i + (cells[0] + 1) * (j + (cells[1] + 1) * k));
  }
};

/// How to build a block.
struct ElasticBlockConfig {
  ElasticNetwork network = ElasticNetwork::Lattice;
  std::array<int, 3> cells{8, 8, 8};
  double cellSizeMm = 1.0;  ///< mm
  ElasticMaterial material{};
  LatticeBoundary latticeBoundary = LatticeBoundary::PerCell;
  TetStiffnessFormula tetFormula = TetStiffnessFormula::LloydIsotropicProjection;
  CubeSplit split = CubeSplit::Five;
};

/// Builds the block's nodes and springs. Fails on bad sizes or a bad material.
Result<ElasticBlock> buildElasticBlock(const ElasticBlockConfig& config);

/// What a uniaxial compression measured.
struct UniaxialResult {
  double forceN = 0.0;             ///< N, the top face's reaction
  double effectiveModulusKpa = 0;  ///< kPa
  double modulusRatio = 0.0;       ///< E_eff / E configured
  double poissonRatio = 0.0;       ///< measured: -(lateral strain) / (axial strain), x faces
};

/// Uniaxial compression of a block of `config.cells` cells: bottom face on rollers (z held), top
/// face on rollers moved down by `strain` (dimensionless, in (0, 0.5)) times the height, one corner
/// held in x and y and another in y (no rigid motion, no lateral constraint; a clamped face would
/// measure the larger constrained modulus). E_eff = (F / A) / strain.
Result<UniaxialResult> measureUniaxial(const ElasticBlockConfig& config, double strain = 0.01);

/// Hertz indentation of a quarter block by a rigid frictionless sphere.
struct IndentationConfig {
  ElasticBlockConfig block{};      ///< block.cells and block.cellSizeMm: the quarter block
  double sphereRadiusMm = 10.0;    ///< R, mm
  std::vector<double> depthsMm{};  ///< d, mm (each <= 0.2 R for Hertz); empty: 0.05, 0.1, 0.15, 0.2 R
  double poissonRatioForHertz = kEffectivePoissonRatio;  ///< nu in E* = E / (1 - nu^2)
};

/// One depth.
struct IndentationPoint {
  double depthMm = 0.0;          ///< mm
  double forceN = 0.0;           ///< N, the full (4 x quarter) contact force
  double hertzN = 0.0;           ///< N, (4/3) E/(1 - nu^2) sqrt(R) d^(3/2)
  double contactRadiusMm = 0.0;  ///< mm, the farthest contact node from the axis
  int contactNodes = 0;          ///< nodes of the quarter block in contact
};

/// The quarter block [0, W] x [0, W] x [0, H] (W, H from config.block) with roller symmetry
/// planes x = 0 and y = 0, bottom on rollers, the sphere's axis the z axis at x = y = 0 touching
/// the top face z = H. Frictionless unilateral contact (Signorini: pressure >= 0, no penetration,
/// one of them zero) on the top nodes, solved exactly on the compliance matrix of the candidate
/// nodes by an active set. Fails on a bad block, radius or depth.
Result<std::vector<IndentationPoint>> indentSphere(const IndentationConfig& config);

/// (4/3) E/(1 - nu^2) sqrt(R) d^(3/2) in N (E in kPa, R and d in mm): Hertz 1882, a rigid sphere
/// on an elastic half-space, contact radius a = sqrt(R d).
double hertzForceN(double youngsModulusKpa, double poissonRatio, double radiusMm, double depthMm);

}  // namespace tissue::sim
