// Scenario files: good ones parse with their units; bad ones fail with one error naming the
// file and the key.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "tissue/scenario/scenario.h"
#include "tissue/sim/units.h"

namespace tissue::scenario {
namespace {

const std::filesystem::path kFile = "/virtual/bad.json";

std::string patchMesh() {
  return (std::filesystem::path(TISSUE_TEST_DATA_DIR) / "meshes" / "patch.obj").string();
}

/// A valid scenario with `extra` spliced in at the top level (or replacing keys given later).
std::string scenarioWith(const std::string& springs, const std::string& extra = "") {
  return R"({"mesh": ")" + patchMesh() + R"(", "springs": )" + springs + R"(, "mass": {"total": 2})" +
         (extra.empty() ? "" : ", " + extra) + "}";
}

/// The error of parsing, or of building the springs, of `text`; empty when both succeed.
std::string errorOf(const std::string& text) {
  auto s = parseScenario(text, kFile);
  if (!s) return s.error().message;
  auto mesh = loadScenarioMesh(*s);
  if (!mesh) return mesh.error().message;
  auto system = buildSystem(*s, *mesh);
  return system ? std::string() : system.error().message;
}

const std::string kSurface = R"({"from": "surface", "stiffness": 0.1})";

/// A scenario with a tissue block and no springs.stiffness nor mass (the tissue's density).
std::string tissueScenario(const std::string& tissue, const std::string& springs = R"({"from": "surface"})",
                           const std::string& extra = "", const std::string& mesh = patchMesh()) {
  return R"({"mesh": ")" + mesh + R"(", "springs": )" + springs + R"(, "tissue": )" + tissue +
         (extra.empty() ? "" : ", " + extra) + "}";
}

/// The springs' stiffness in N/mm.
std::vector<double> stiffnessNPerMm(const sim::SpringNetwork& springs) {
  std::vector<double> k;
  for (double v : springs.stiffness)
    k.push_back(v / sim::kStiffnessPerNewtonPerMm);
  return k;
}

TEST(ScenarioParse, TissueBlockMakesShellSpringsFromYoungsModulus) {
  const std::string text =
      tissueScenario(R"({"youngs_modulus_kpa": 5, "thickness_mm": 2, "bending_fraction": 0.1})");
  auto s = parseScenario(text, kFile);
  ASSERT_TRUE(s.ok()) << s.error().message;
  ASSERT_TRUE(s->tissue.has_value());
  EXPECT_DOUBLE_EQ(s->tissue->material.youngsModulusKpa, 5.0);
  EXPECT_DOUBLE_EQ(s->mass.total, 0.0);
  EXPECT_DOUBLE_EQ(s->mass.arealDensity, 1.06e-3 * 2.0);  // density times thickness, g/mm^2
  EXPECT_TRUE(s->warnings.empty());
  auto mesh = loadScenarioMesh(*s);
  ASSERT_TRUE(mesh.ok());
  auto system = buildSystem(*s, *mesh);
  ASSERT_TRUE(system.ok()) << system.error().message;
  // Twice the modulus, twice every spring (and the bending springs exist).
  auto stiffer = parseScenario(tissueScenario(R"({"youngs_modulus_kpa": 10, "thickness_mm": 2})"), kFile);
  ASSERT_TRUE(stiffer.ok());
  auto system2 = buildSystem(*stiffer, *mesh);
  ASSERT_TRUE(system2.ok());
  const auto k1 = stiffnessNPerMm(system->springs), k2 = stiffnessNPerMm(system2->springs);
  ASSERT_EQ(k1.size(), k2.size());
  auto plain = parseScenario(scenarioWith(kSurface), kFile);
  ASSERT_TRUE(plain.ok());
  EXPECT_GT(k1.size(), buildSystem(*plain, *mesh)->springs.size());  // bending springs were built
  for (std::size_t i = 0; i < k1.size(); ++i) {
    EXPECT_GT(k1[i], 0.0);
    EXPECT_NEAR(k2[i], 2.0 * k1[i], 1e-12 * k2[i]);
  }
}

TEST(ScenarioParse, TissueBlockOnALatticeUsesTheCellFormulaAndTheDensity) {
  const std::string liver = (std::filesystem::path(TISSUE_TEST_DATA_DIR) / "meshes" / "liver.obj").string();
  auto s = parseScenario(tissueScenario(R"({"youngs_modulus_kpa": 4.5, "poisson_ratio": 0.45})",
                                        R"({"from": "lattice"})", R"("lattice": {"cell_size": 16})", liver),
                         kFile);
  ASSERT_TRUE(s.ok()) << s.error().message;
  EXPECT_DOUBLE_EQ(s->massVolumeDensity, 1.06e-3);
  ASSERT_EQ(s->warnings.size(), 1u);  // nu = 0.45 is reported, the springs realise 0.25
  EXPECT_NE(s->warnings[0].find("bad.json: tissue.poisson_ratio"), std::string::npos) << s->warnings[0];
  auto mesh = loadScenarioMesh(*s);
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  auto system = buildSystem(*s, *mesh);
  ASSERT_TRUE(system.ok()) << system.error().message;
  // Interior springs get k1 = k2 = mu a (mu = 2E/5); boundary ones a share; body diagonals 0.
  const auto k = stiffnessNPerMm(system->springs);
  const double interior = sim::latticeInteriorStiffness(4.5, 16.0).edge;
  EXPECT_NEAR(*std::max_element(k.begin(), k.end()), interior, 1e-12);
  EXPECT_NEAR(interior, 0.4 * 4.5e-3 * 16.0, 1e-15);
  // Masses: the density times the filled volume.
  double total = 0.0;
  for (double m : system->masses)
    total += m;
  EXPECT_NEAR(total, 1.06e-3 * mesh->lattice->filledVolume, 1e-9 * total);
}

TEST(ScenarioParse, AGoodScenarioKeepsItsValuesAndUnits) {
  const std::string text = scenarioWith(
      R"({"from": "surface", "stiffness": 0.3, "stiffness_law": "per-rest-length", "bending_stiffness": 0.05})",
      R"("damping": {"springs": 0.001, "rayleigh_mass": 1.5}, "gravity": [0, -9806.65, 0], "pinned": [0, 1, 2],
         "integrator": "verlet", "dt": 0.01, "substeps": 4, "frames": 7,
         "instrument": {"shape": "capsule", "radius": 2, "length": 10, "axis": [1, 0, 0],
                        "path": [{"time": 0, "position": [0, 0, 5]}, {"time": 1, "position": [0, 0, -5], "axis": [0, 1, 0]}],
                        "actions": [{"time": 0.5, "action": "grasp"}]})");
  auto s = parseScenario(text, kFile);
  ASSERT_TRUE(s.ok()) << s.error().message;
  EXPECT_EQ(s->springSource, SpringSource::Surface);
  EXPECT_EQ(s->springs.law, sim::StiffnessLaw::PerRestLength);
  EXPECT_DOUBLE_EQ(s->springs.stiffness, 0.3);
  EXPECT_DOUBLE_EQ(s->springs.damping, 0.001);
  EXPECT_DOUBLE_EQ(s->system.rayleighMass, 1.5);
  EXPECT_DOUBLE_EQ(s->mass.total, 2.0);
  EXPECT_EQ(s->pinnedIndices.size(), 3u);
  EXPECT_EQ(s->integrator, sim::Integrator::VelocityVerlet);
  EXPECT_EQ(s->substeps, 4);
  EXPECT_EQ(s->frames, 7);
  ASSERT_TRUE(s->instrument.has_value());
  EXPECT_EQ(s->instrument->config.shape.kind, sim::ToolShapeKind::Capsule);
  EXPECT_DOUBLE_EQ(s->instrument->path[0].pose.axis.x, 1.0);
  EXPECT_DOUBLE_EQ(s->instrument->path[1].pose.axis.y, 1.0);
  EXPECT_TRUE(s->instrument->actions[0].grasp);
  EXPECT_EQ(errorOf(text), "");
}

TEST(ScenarioParse, TheDataScenarioParsesAndResolvesItsMesh) {
  auto s = loadScenario(std::filesystem::path(TISSUE_TEST_DATA_DIR) / "scenarios" / "liver_poke_grasp.json");
  ASSERT_TRUE(s.ok()) << s.error().message;
  EXPECT_TRUE(std::filesystem::exists(s->mesh));
  EXPECT_EQ(s->frames, 1000);
}

TEST(ScenarioParse, SharedMeshesResolve) {
  const std::filesystem::path shared = std::filesystem::path(TISSUE_TEST_SHARED_DIR) / "meshes";
  if (!std::filesystem::exists(shared / "liver-smooth.obj")) GTEST_FAIL() << "no shared meshes";
  auto s = parseScenario(
      R"({"mesh": "liver-smooth.obj", "springs": {"from": "surface", "stiffness": 1}, "mass": {"total": 1}})",
      kFile, {.sharedMeshesDir = shared});
  ASSERT_TRUE(s.ok()) << s.error().message;
  EXPECT_EQ(s->mesh, shared / "liver-smooth.obj");
}

TEST(ScenarioParse, TissueBlockOnTetsMeetsTheIsotropicProjectionIdentity) {
  // k = 6 E V_t / sum_e l_e^2 on each tet's edges: summed over the mesh, sum_s k_s l_s^2 = 6 E V.
  const std::filesystem::path msh = std::filesystem::path(TISSUE_TEST_SHARED_DIR) / "meshes" / "liver.msh";
  if (!std::filesystem::exists(msh)) GTEST_FAIL() << "no shared liver.msh";
  auto s = parseScenario(tissueScenario(R"({"youngs_modulus_kpa": 6})", R"({"from": "tet-edges"})",
                                        R"("mesh_scale_to_mm": 25)", msh.string()),
                         kFile);
  ASSERT_TRUE(s.ok()) << s.error().message;
  auto mesh = loadScenarioMesh(*s);
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  auto system = buildSystem(*s, *mesh);
  ASSERT_TRUE(system.ok()) << system.error().message;
  double volume = 0.0;
  for (const Tet& t : mesh->tets) {
    const auto p = [&](int c) {
      const Float3& q = mesh->positions[t[c]];
      return sim::Vec3d{q.x, q.y, q.z};
    };
    const sim::Vec3d a = p(1) - p(0), b = p(2) - p(0), c = p(3) - p(0);
    volume += std::abs(a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) +
                       a.z * (b.x * c.y - b.y * c.x)) /
              6.0;
  }
  double sumKL2 = 0.0, mass = 0.0;
  const auto k = stiffnessNPerMm(system->springs);
  for (std::size_t i = 0; i < k.size(); ++i)
    sumKL2 += k[i] * system->springs.restLength[i] * system->springs.restLength[i];
  for (double m : system->masses)
    mass += m;
  EXPECT_NEAR(sumKL2, 6.0 * 6.0e-3 * volume, 1e-4 * sumKL2);  // E = 6 kPa = 6e-3 N/mm^2
  EXPECT_NEAR(mass, 1.06e-3 * volume, 1e-4 * mass);           // the tissue's density
}

struct BadCase {
  std::string text, mustContain;
};

TEST(ScenarioParse, EveryBadScenarioNamesTheFileAndTheKey) {
  const std::vector<BadCase> cases{
      {scenarioWith(R"({"from": "surface", "stiffness": -3})"),
       "bad.json: springs.stiffness: expected a positive number (N/mm), got -3"},
      {scenarioWith(R"({"from": "surface", "stifness": 3})"), "springs.stifness: unknown key"},
      {scenarioWith(kSurface, R"("gravty": [0, 0, -9806])"), "gravty: unknown key"},
      {scenarioWith(R"({"from": "voxels", "stiffness": 1})"), "springs.from: expected one of"},
      {scenarioWith(R"({"from": "tet-edges", "stiffness": 1})"),
       "mesh: springs.from = \"tet-edges\" needs a tetrahedral mesh"},
      // The patch is open: a lattice needs a closed surface to fill.
      {scenarioWith(R"({"from": "lattice", "stiffness": 1})", R"("lattice": {"cell_size": 5})"),
       "springs.from: \"lattice\": "},
      {scenarioWith(R"({"from": "lattice", "stiffness": 1})"), "lattice: missing"},
      {scenarioWith(kSurface, R"("gravity": [0, -9806])"), "gravity: expected [x, y, z] (mm/s^2)"},
      {scenarioWith(kSurface, R"("integrator": "rk4")"), "integrator: expected one of"},
      {scenarioWith(kSurface, R"("dt": 0)"), "dt: expected a positive number (s per frame), got 0"},
      {scenarioWith(kSurface, R"("frames": 2.5)"), "frames: expected a positive integer"},
      {scenarioWith(kSurface, R"("pinned": [0, -1])"), "pinned[1]: expected a vertex index"},
      {scenarioWith(kSurface, R"("pinned": [0, 99999999])"), "pinned[1]: vertex 99999999 is not a vertex"},
      {scenarioWith(kSurface, R"("pinned": {"axis": "w", "below": 0})"), "pinned.axis: expected one of"},
      {scenarioWith(kSurface, R"("pinned": {"axis": "z", "below": -1000})"), "pinned.below: pins no vertex"},
      {scenarioWith(kSurface, R"("damping": -1)"), "damping: expected a number >= 0 (N*s/mm)"},
      {R"({"mesh": ")" + patchMesh() +
           R"(", "springs": {"from": "surface", "stiffness": 1}, "mass": {"total": 1, "density": 0.001}})",
       "mass: give exactly one of total"},
      {R"({"mesh": ")" + patchMesh() +
           R"(", "springs": {"from": "surface", "stiffness": 1}, "mass": {"total": 1, "distribution": "even"}})",
       "mass.distribution: expected one of"},
      {R"({"mesh": "nowhere.obj", "springs": {"from": "surface", "stiffness": 1}, "mass": {"total": 1}})",
       "mesh: no file"},
      {R"({"springs": {"from": "surface", "stiffness": 1}, "mass": {"total": 1}})", "mesh: missing"},
      {scenarioWith(
           kSurface,
           R"("instrument": {"shape": "cube", "radius": 1, "path": [{"time": 0, "position": [0, 0, 0]}]})"),
       "instrument.shape: expected one of"},
      {scenarioWith(
           kSurface,
           R"("instrument": {"shape": "sphere", "radius": 0, "path": [{"time": 0, "position": [0, 0, 0]}]})"),
       "instrument.radius: expected a positive number (mm), got 0"},
      {scenarioWith(
           kSurface,
           R"("instrument": {"shape": "capsule", "radius": 1, "path": [{"time": 0, "position": [0, 0, 0]}]})"),
       "instrument.length: missing"},
      {scenarioWith(
           kSurface,
           R"("instrument": {"shape": "sphere", "radius": 1, "path": [{"time": 1, "position": [0, 0, 0]}, {"time": 0.5, "position": [0, 0, 1]}]})"),
       "instrument.path[1].time: keyframe times must increase"},
      {scenarioWith(
           kSurface,
           R"("instrument": {"shape": "sphere", "radius": 1, "path": [{"time": 0, "position": [0, 0]}]})"),
       "instrument.path[0].position: expected [x, y, z] (mm)"},
      {scenarioWith(
           kSurface,
           R"("instrument": {"shape": "sphere", "radius": 1, "path": [{"time": 0, "position": [0, 0, 0]}], "actions": [{"time": 1, "action": "pinch"}]})"),
       "instrument.actions[0].action: expected one of"},
      {"{\"mesh\": ", "bad.json: not valid JSON"},
      // A number beyond a double: nlohmann throws out_of_range, not parse_error (the fuzz target).
      {"7777777777e77777777000000000000", "bad.json: not valid JSON"},
      // The tissue block (material constants).
      {tissueScenario(R"({"youngs_modulus_kpa": -3})"),
       "bad.json: tissue.youngs_modulus_kpa: expected a positive number (kPa), got -3"},
      {tissueScenario(R"({"youngs_modulus_kpa": 5, "poisson_ratio": 0.5})"),
       "bad.json: tissue.poisson_ratio: expected a number in (0, 0.5)"},
      {tissueScenario(R"({"youngs_modulus_kpa": 5, "poisson_ratio": -0.1})"),
       "tissue.poisson_ratio: expected"},
      {tissueScenario(R"({"youngs_modulus_kpa": 5, "density_g_per_mm3": 0})"),
       "tissue.density_g_per_mm3: expected a positive number (g/mm^3), got 0"},
      {tissueScenario(R"({"youngs_modulus_kpa": 5, "thickness_mm": 0})"),
       "tissue.thickness_mm: expected a positive number (mm), got 0"},
      {tissueScenario(R"({"poisson_ratio": 0.3})"), "tissue.youngs_modulus_kpa: missing"},
      {tissueScenario(R"({"youngs_modulus": 5})"), "tissue.youngs_modulus: unknown key"},
      {tissueScenario(R"({"youngs_modulus_kpa": 5})", R"({"from": "surface", "stiffness": 0.1})"),
       "springs.stiffness: give either springs.stiffness (per-spring values) or the tissue block"},
      {tissueScenario(R"({"youngs_modulus_kpa": 5})", R"({"from": "surface", "bending_stiffness": 0.1})"),
       "springs.bending_stiffness: give either"},
      {tissueScenario(R"({"youngs_modulus_kpa": 5, "thickness_mm": 2})", R"({"from": "lattice"})",
                      R"("lattice": {"cell_size": 5})"),
       "tissue.thickness_mm: only for springs.from = \"surface\""},
      {R"({"mesh": ")" + patchMesh() + R"(", "springs": {"from": "surface"}, "mass": {"total": 1}})",
       "springs.stiffness: missing; give a positive number (N/mm), or a tissue block"},
  };
  for (const auto& c : cases) {
    const std::string error = errorOf(c.text);
    EXPECT_NE(error.find(c.mustContain), std::string::npos)
        << "scenario " << c.text << "\n  error: " << error;
    EXPECT_NE(error.find("bad.json"), std::string::npos) << error;
  }
}

}  // namespace
}  // namespace tissue::scenario
