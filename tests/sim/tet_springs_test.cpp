// Tet-edge springs and volume masses on a hand-built two-tet mesh.
#include <gtest/gtest.h>

#include <numeric>

#include "tissue/sim/mass.h"
#include "tissue/sim/tet_springs.h"
#include "tissue/sim/units.h"

namespace tissue::sim {
namespace {

// Two tets sharing the face (1, 2, 3): volumes 1/6 and 2/6 mm^3 (times scale^3).
const std::vector<Float3> kPoints = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {0, 0, 10}, {10, 10, 10}};
const std::vector<Tet> kTets = {{0, 1, 2, 3}, {1, 2, 3, 4}};

TEST(TetSprings, OneSpringPerUniqueEdge) {
  TetSpringReport report;
  auto net = buildTetEdgeSprings(kPoints, kTets, {.stiffness = 0.2}, &report);
  ASSERT_TRUE(net.ok()) << net.error().message;
  // 6 + 6 edges, the shared face's 3 counted once.
  EXPECT_EQ(net->size(), 9u);
  EXPECT_EQ(report.edgeSprings, 9u);
  EXPECT_EQ(net->vertexCount(), 5u);
  for (std::size_t e = 0; e < net->size(); ++e) {
    EXPECT_NE(net->i[e], net->j[e]);
    EXPECT_DOUBLE_EQ(net->stiffness[e], stiffnessFromNewtonPerMm(0.2));
  }
  // The missing pair is (0, 4): the only two vertices that share no tet.
  for (std::size_t e = 0; e < net->size(); ++e)
    EXPECT_FALSE(net->i[e] == 0 && net->j[e] == 4);
}

TEST(TetSprings, PerRestLengthLawScalesByLength) {
  auto net = buildTetEdgeSprings(kPoints, kTets, {.stiffness = 3.0, .law = StiffnessLaw::PerRestLength});
  ASSERT_TRUE(net.ok());
  for (std::size_t e = 0; e < net->size(); ++e)
    EXPECT_NEAR(net->stiffness[e] * net->restLength[e], stiffnessFromNewtonPerMm(3.0), 1e-6);
}

TEST(TetSprings, BadIndexIsAnError) {
  const std::vector<Tet> bad = {{0, 1, 2, 9}};
  auto net = buildTetEdgeSprings(kPoints, bad, {});
  ASSERT_FALSE(net.ok());
  EXPECT_NE(net.error().message.find("tet 1"), std::string::npos) << net.error().message;
}

TEST(TetMasses, LumpedByVolumeSumsToTotalAndFollowsVolume) {
  auto m = computeTetMasses(kPoints, kTets, {.total = 12.0});
  ASSERT_TRUE(m.ok()) << m.error().message;
  EXPECT_NEAR(std::accumulate(m->begin(), m->end(), 0.0), 12.0, 1e-12);
  // Vertex 0 only in the small tet (V), vertex 4 only in the big one (2V): twice the mass.
  EXPECT_NEAR((*m)[4], 2.0 * (*m)[0], 1e-12);
  EXPECT_NEAR((*m)[0], 12.0 * (1.0 / 4.0) / 3.0, 1e-12);
}

TEST(TetMasses, DensityTimesVolume) {
  const double density = 1.06e-3;  // g/mm^3
  auto m = computeTetMasses(kPoints, kTets, {.total = 0.0, .density = density});
  ASSERT_TRUE(m.ok());
  const double volume = 1000.0 / 6.0 + 2000.0 / 6.0;  // mm^3
  EXPECT_NEAR(std::accumulate(m->begin(), m->end(), 0.0), density * volume, 1e-12);
}

TEST(TetMasses, UniformGivesEveryVertexTheSame) {
  auto m = computeTetMasses(kPoints, kTets, {.total = 5.0, .distribution = MassDistribution::Uniform});
  ASSERT_TRUE(m.ok());
  for (double v : *m)
    EXPECT_DOUBLE_EQ(v, 1.0);
}

TEST(TetMasses, InvertedTetAndLonelyVertexAreErrors) {
  const std::vector<Tet> inverted = {{0, 2, 1, 3}};
  EXPECT_FALSE(computeTetMasses(kPoints, inverted, {.total = 1.0}).ok());
  const std::vector<Tet> one = {{0, 1, 2, 3}};  // vertex 5 (1-based) in no tet
  auto m = computeTetMasses(kPoints, one, {.total = 1.0});
  ASSERT_FALSE(m.ok());
  EXPECT_NE(m.error().message.find("vertex 5"), std::string::npos) << m.error().message;
  EXPECT_TRUE(computeTetMasses(kPoints, one, {.total = 1.0, .distribution = MassDistribution::Uniform}).ok());
}

}  // namespace
}  // namespace tissue::sim
