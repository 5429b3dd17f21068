// The stability study on the organ: the data liver on a coarse lattice under a short poke. An
// explicit-family integrator has a finite largest stable step that shrinks as the tissue
// stiffens (h ~ 1/omega ~ 1/sqrt(E)); implicit Euler is stable at every step tried; the 60 Hz
// cost row exists for every integrator that is stable somewhere.
#include <gtest/gtest.h>

#include <cmath>

#include "tissue/scenario/organ_stability.h"

namespace tissue::scenario {
namespace {

Scenario coarseLiver() {
  const std::string text = R"({"mesh": ")" +
                           (std::filesystem::path(TISSUE_TEST_DATA_DIR) / "meshes" / "liver.obj").string() +
                           R"(",
    "springs": {"from": "lattice"}, "lattice": {"cell_size": 20},
    "tissue": {"youngs_modulus_kpa": 5},
    "damping": {"springs": 0.00002, "rayleigh_mass": 5.0},
    "gravity": [0, 0, -9806.65], "pinned": {"axis": "z", "below": -13},
    "instrument": {"shape": "sphere", "radius": 8, "path": [
      {"time": 0.0, "position": [31.82, 0, 62]}, {"time": 0.4, "position": [31.82, 0, 50]}]}})";
  auto s = parseScenario(text, std::filesystem::path(TISSUE_TEST_OUTPUT_DIR) / "organ_stability.json");
  EXPECT_TRUE(s.ok()) << s.error().message;
  return *s;
}

TEST(OrganStability, ExplicitLimitsShrinkWithStiffnessImplicitHasNone) {
  OrganStabilityConfig config;
  config.youngsModuliKpa = {5.0, 80.0};
  config.integrators = {sim::Integrator::SymplecticEuler, sim::Integrator::ImplicitEuler};
  config.windowS = 0.4;
  config.bisections = 5;
  auto rows = runOrganStabilityStudy(coarseLiver(), config);
  ASSERT_TRUE(rows.ok()) << rows.error().message;
  ASSERT_EQ(rows->size(), 4u);
  const auto& soft = (*rows)[0];
  const auto& stiff = (*rows)[2];
  ASSERT_EQ(soft.integrator, sim::Integrator::SymplecticEuler);
  ASSERT_TRUE(soft.maxStableStepS && stiff.maxStableStepS);
  EXPECT_FALSE(soft.stableAtMaxTested);
  EXPECT_FALSE(stiff.stableAtMaxTested);
  // 16 times stiffer: the limit scales as 1/sqrt(E), a factor 4 (the bisection's 2^(1/32) steps
  // in log range and the damping's share leave a band).
  const double ratio = *soft.maxStableStepS / *stiff.maxStableStepS;
  EXPECT_GT(ratio, 2.5);
  EXPECT_LT(ratio, 6.0);
  for (const auto* r : {&(*rows)[1], &(*rows)[3]}) {
    EXPECT_EQ(r->integrator, sim::Integrator::ImplicitEuler);
    EXPECT_TRUE(r->stableAtMaxTested);
    ASSERT_TRUE(r->substepsPerFrame);
    EXPECT_EQ(*r->substepsPerFrame, 1);
  }
  // The cost rows: a stable 60 Hz frame needs at least frame / limit substeps.
  for (const auto& r : *rows)
    if (r.maxStableStepS && !r.stableAtMaxTested) {
      ASSERT_TRUE(r.substepsPerFrame);
      EXPECT_GE(*r.substepsPerFrame, static_cast<int>(std::ceil(config.frameS / *r.maxStableStepS)));
      EXPECT_GT(r.msPerFrameMedian, 0.0);
    }
}

TEST(OrganStability, AScenarioWithoutMaterialConstantsIsRefusedWithTheFix) {
  Scenario s = coarseLiver();
  s.tissue.reset();
  auto rows = runOrganStabilityStudy(s, {});
  ASSERT_FALSE(rows.ok());
  EXPECT_NE(rows.error().message.find("give the tissue as a \"tissue\" block"), std::string::npos);
}

}  // namespace
}  // namespace tissue::scenario
