// The re-fit under the simulator (issue 11) on the data scenario: the exact incremental path is
// a full re-fit (PlaneRefitSettings: bound 0 is bit-identical), the tolerant one stays within its
// bound and re-fits no more planes, and the motion histogram is monotone in the step.
#include <gtest/gtest.h>

#include <filesystem>

#include "tissue/mesh/load_mesh.h"
#include "tissue/scenario/scenario.h"
#include "tissue/studies/refit_study.h"

namespace tissue::studies {
namespace {

TEST(RefitScenarioStudy, ExactMatchesFullAndTolerantKeepsItsBound) {
  const std::filesystem::path data = TISSUE_TEST_DATA_DIR, shared = TISSUE_TEST_SHARED_DIR;
  auto parsed = scenario::loadScenario(data / "scenarios" / "liver_poke_grasp.json",
                                       {.sharedMeshesDir = shared / "meshes"});
  ASSERT_TRUE(parsed) << parsed.error().message;
  auto loaded = mesh::loadMesh(parsed->mesh, {.requireUvs = true, .scaleToMm = float(parsed->meshScaleToMm)});
  ASSERT_TRUE(loaded) << loaded.error().message;
  const double bound = 1e-4;  // rad
  auto study = studyRefitUnderScenario(*parsed, *loaded, mesh::PlaneFitSettings{}, bound, 6);
  ASSERT_TRUE(study) << study.error().message;
  EXPECT_EQ(study->frames, 6);
  EXPECT_GT(study->vertices, 1000u);
  EXPECT_LT(study->exact.maxNormalDeviationRad, 1e-6);
  EXPECT_LT(study->exact.maxOffsetDeviationMm, 1e-6);
  EXPECT_LE(study->tolerant.maxNormalDeviationRad, bound * 1.05);
  EXPECT_LE(study->tolerant.meanRefittedFraction, study->exact.meanRefittedFraction);
  EXPECT_DOUBLE_EQ(study->exact.maxNormalErrorRad, 0.0);
  EXPECT_DOUBLE_EQ(study->tolerant.maxNormalErrorRad, bound);
  for (std::size_t k = 1; k < study->meanFractionBeyond.size(); ++k)
    EXPECT_LE(study->meanFractionBeyond[k], study->meanFractionBeyond[k - 1]);
  EXPECT_LE(study->meanFractionBeyond[0], study->meanChangedVertexFraction);
  EXPECT_LE(study->toleranceMmP10, study->toleranceMmMedian);
  EXPECT_LE(study->toleranceMmMedian, study->toleranceMmP90);
}

TEST(RefitScenarioStudy, RefusesAMeshOfAnotherSize) {
  const std::filesystem::path data = TISSUE_TEST_DATA_DIR, shared = TISSUE_TEST_SHARED_DIR;
  auto parsed = scenario::loadScenario(data / "scenarios" / "liver_poke_grasp.json",
                                       {.sharedMeshesDir = shared / "meshes"});
  ASSERT_TRUE(parsed);
  auto patch = mesh::loadMesh(data / "meshes" / "patch.obj", {.requireUvs = true});
  ASSERT_TRUE(patch) << patch.error().message;
  auto study = studyRefitUnderScenario(*parsed, *patch, mesh::PlaneFitSettings{}, 1e-4, 1);
  ASSERT_FALSE(study);
  EXPECT_NE(study.error().message.find("vertices"), std::string::npos);
}

}  // namespace
}  // namespace tissue::studies
