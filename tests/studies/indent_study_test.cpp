// The indent study: option names round-trip, one row per depth and network, the force growing with depth.
#include "tissue/studies/indent_study.h"

#include <gtest/gtest.h>

namespace tissue::studies {
namespace {

TEST(IndentStudy, NamesRoundTrip) {
  for (auto f : {sim::TetStiffnessFormula::LloydIsotropicProjection, sim::TetStiffnessFormula::Lloyd2007,
                 sim::TetStiffnessFormula::VanGelder1998})
    EXPECT_EQ(parseTetFormula(tetFormulaName(f)), f);
  for (auto b : {sim::LatticeBoundary::PerCell, sim::LatticeBoundary::InteriorValue})
    EXPECT_EQ(parseLatticeBoundary(latticeBoundaryName(b)), b);
  EXPECT_FALSE(parseTetFormula("foo"));
  EXPECT_FALSE(parseLatticeBoundary("foo"));
}

TEST(IndentStudy, OneRowPerDepthAndNetworkForceGrowingWithDepth) {
  IndentStudyConfig config;
  config.cells = 8;
  config.cellsPerRadius = 3;
  config.sphereRadiusMm = 6.0;
  auto study = runIndentStudy(config);
  ASSERT_TRUE(study) << study.error().message;
  ASSERT_EQ(study->networks.size(), 2u);
  EXPECT_DOUBLE_EQ(study->cellSizeMm, 2.0);
  for (const auto& n : study->networks) {
    ASSERT_EQ(n.points.size(), 4u);                      // 0.05, 0.1, 0.15, 0.2 R
    for (std::size_t k = 1; k < n.points.size(); ++k) {  // deeper presses harder, as Hertz's d^(3/2)
      EXPECT_GT(n.points[k].depthMm, n.points[k - 1].depthMm);
      EXPECT_GT(n.points[k].forceN, n.points[k - 1].forceN) << networkName(n.network);
      EXPECT_GT(n.points[k].hertzN, n.points[k - 1].hertzN);
    }
  }
  const std::string json = indentStudyJson(*study);
  for (const char* key : {"\"uniaxial_modulus_ratio_lattice\"", "\"uniaxial_modulus_ratio_tets\"",
                          "\"network\": \"tets\"", "\"tet_formula\": \"lloyd-isotropic-projection\""})
    EXPECT_NE(json.find(key), std::string::npos) << key;
}

}  // namespace
}  // namespace tissue::studies
