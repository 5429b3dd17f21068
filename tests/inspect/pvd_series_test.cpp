// The ParaView time series: a 100-frame simulated run through the library's loop into a .pvd,
// read back with VTK's XML readers (every frame, every array, 100 increasing time steps), a
// lattice organ's frame as a .vtu with cell data, atomic writes and the errors.
#include "tissue/inspect/pvd_series.h"

#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "../scene/loop_fixture.h"
#include "tissue/mesh/load_mesh.h"
#include "tissue/scenario/scenario_run.h"
#include "tissue/scene/organ_loop.h"
#include "tissue/scene/scene.h"

namespace tissue::inspect {
namespace {

namespace fs = std::filesystem;

const char* const kPointArrays[] = {"velocity_mm_per_s", "stretch",      "strain",
                                    "contact_force_N",   "plane_normal", "plane_offset_mm",
                                    "plane_residual_mm", "tangent",      "normal"};

fs::path outDir(const char* name) {
  return fs::path(TISSUE_TEST_OUTPUT_DIR) / "inspect" / name;
}

/// (timestep, file) of every DataSet of a .pvd.
std::vector<std::pair<double, std::string>> readPvd(const fs::path& pvd) {
  std::ifstream in(pvd);
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  const std::regex entry(R"re(<DataSet timestep="([^"]+)"[^>]*file="([^"]+)")re");
  std::vector<std::pair<double, std::string>> out;
  for (auto it = std::sregex_iterator(s.begin(), s.end(), entry); it != std::sregex_iterator(); ++it)
    out.emplace_back(std::stod((*it)[1].str()), (*it)[2].str());
  return out;
}

TEST(PvdSeries, AHundredFrameRunReadsBackWithEveryArrayAndTimeStep) {
  const fs::path dir = outDir("pvd_series");
  fs::remove_all(dir);
  auto s = scenario::loadScenario(test::writePokedGrid(dir / "scenario", 15, 2.0, 100));
  ASSERT_TRUE(s.ok()) << s.error().message;
  auto mesh = mesh::loadMesh(s->mesh, {.requireUvs = true});
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  auto loop = scene::OrganLoop::create(*s, std::move(*mesh));
  ASSERT_TRUE(loop.ok()) << loop.error().message;
  auto series = PvdSeries::create(dir / "series", "grid");
  ASSERT_TRUE(series.ok()) << series.error().message;
  for (int f = 0; f < 100; ++f) {
    ASSERT_TRUE(loop->advance().ok());
    auto cost = series->addFrame(snapshotOf(loop->run(), loop->surface()));
    ASSERT_TRUE(cost.ok()) << cost.error().message;
  }
  EXPECT_EQ(series->frameCount(), 100u);

  // The collection: 100 data sets, increasing times one frame apart, files that exist.
  const auto entries = readPvd(series->pvdPath());
  ASSERT_EQ(entries.size(), 100u);
  for (std::size_t i = 0; i < entries.size(); ++i) {
    EXPECT_NEAR(entries[i].first, double(i + 1) * s->frameTime, 1e-12);
    EXPECT_TRUE(fs::exists(dir / "series" / entries[i].second)) << entries[i].second;
  }
  // Every frame through VTK's reader: the points and every array, one tuple per point.
  const std::size_t vertices = loop->surface().geometricPositions().size();
  double firstZ = 0.0, lastZ = 0.0, maxContact = 0.0;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName((dir / "series" / entries[i].second).c_str());
    reader->Update();
    vtkPolyData* poly = reader->GetOutput();
    ASSERT_EQ(std::size_t(poly->GetNumberOfPoints()), vertices) << entries[i].second;
    ASSERT_EQ(std::size_t(poly->GetNumberOfPolys()), loop->surface().geometricTriangles().size());
    for (const char* name : kPointArrays) {
      vtkDataArray* a = poly->GetPointData()->GetArray(name);
      ASSERT_NE(a, nullptr) << name << " in " << entries[i].second;
      EXPECT_EQ(std::size_t(a->GetNumberOfTuples()), vertices) << name;
    }
    ASSERT_NE(poly->GetCellData()->GetArray("strain"), nullptr);
    // The centre vertex (7, 7) of the 15 x 15 grid: pushed down by the tool.
    const double z = poly->GetPoint(7 * 15 + 7)[2];
    if (i == 0) firstZ = z;
    lastZ = z;
    vtkDataArray* contact = poly->GetPointData()->GetArray("contact_force_N");
    for (vtkIdType p = 0; p < contact->GetNumberOfTuples(); ++p)
      maxContact = std::max(maxContact, std::fabs(contact->GetComponent(p, 2)));
  }
  EXPECT_NEAR(firstZ, 0.0, 1e-3);
  EXPECT_LT(lastZ, -0.5);  // the tool holds the centre 2 mm down
  EXPECT_GT(maxContact, 0.0);
  // Written atomically: no temporary file is left beside the series.
  for (const auto& file : fs::directory_iterator(dir / "series"))
    EXPECT_EQ(file.path().filename().string().find(".tmp"), std::string::npos) << file.path();
}

TEST(PvdSeries, ALatticeOrgansFrameIsAnUnstructuredGridWithCellData) {
  const fs::path scenarioFile = fs::path(TISSUE_TEST_DATA_DIR) / "scenarios" / "liver_poke_grasp.json";
  auto organ = scene::loadSimulatedOrgan({.scenario = scenarioFile});
  ASSERT_TRUE(organ.ok()) << organ.error().message;
  auto loop = scene::OrganLoop::create(organ->scenario, organ->assets.mesh, {.planes = organ->assets.planes});
  ASSERT_TRUE(loop.ok()) << loop.error().message;
  ASSERT_TRUE(loop->advance().ok());
  const OrganSnapshot snap = snapshotOf(loop->run(), loop->surface());
  ASSERT_FALSE(snap.nodes.hexes.empty());
  auto path = writeOrganFrame(snap, outDir("pvd_lattice") / "liver");
  ASSERT_TRUE(path.ok()) << path.error().message;
  EXPECT_EQ(path->extension(), ".vtu");
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path->c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  const std::size_t points = snap.nodes.positions.size() + snap.surface.positions.size();
  const std::size_t cells = snap.nodes.hexes.size() + snap.surface.triangles.size();
  ASSERT_EQ(std::size_t(grid->GetNumberOfPoints()), points);
  ASSERT_EQ(std::size_t(grid->GetNumberOfCells()), cells);
  EXPECT_EQ(grid->GetCellType(0), VTK_HEXAHEDRON);
  EXPECT_EQ(grid->GetCellType(vtkIdType(cells - 1)), VTK_TRIANGLE);
  for (const char* name : kPointArrays) {
    vtkDataArray* a = grid->GetPointData()->GetArray(name);
    ASSERT_NE(a, nullptr) << name;
    EXPECT_EQ(std::size_t(a->GetNumberOfTuples()), points) << name;
  }
  for (const char* name : {"strain", "surface"}) {
    vtkDataArray* a = grid->GetCellData()->GetArray(name);
    ASSERT_NE(a, nullptr) << name;
    EXPECT_EQ(std::size_t(a->GetNumberOfTuples()), cells) << name;
  }
  // A hexahedron's corners in VTK order: corner 6 is diagonally opposite corner 0.
  double p0[3], p6[3];
  grid->GetCell(0)->GetPoints()->GetPoint(0, p0);
  grid->GetCell(0)->GetPoints()->GetPoint(6, p6);
  for (int k = 0; k < 3; ++k)
    EXPECT_GT(std::fabs(p6[k] - p0[k]), 1.0) << "axis " << k;
}

TEST(RunSeries, ATetMeshRunWritesUnstructuredGridsWithTetsAndTheBoundary) {
  // The SOFA liver's tet mesh (181 vertices, 596 tets) hanging under gravity: a bare run, as
  // `simulate` has it; its boundary has no UVs (the planar projection stands in).
  const fs::path msh = fs::path(TISSUE_TEST_SHARED_DIR) / "meshes" / "liver.msh";
  const std::string text = R"({"mesh": ")" + msh.string() + R"(", "mesh_scale_to_mm": 25,
    "springs": {"from": "tet-edges", "stiffness": 0.05, "stiffness_law": "constant"},
    "mass": {"total": 1500, "distribution": "lumped"}, "gravity": [0, 0, -9806.65],
    "damping": {"springs": 0.0002, "rayleigh_mass": 5.0}, "pinned": [0, 1, 2, 3, 4, 5],
    "integrator": "implicit-euler", "frames": 10})";
  auto s = scenario::parseScenario(text, outDir("run_series") / "tets.json");
  ASSERT_TRUE(s.ok()) << s.error().message;
  auto run = scenario::ScenarioRun::create(*s);
  ASSERT_TRUE(run.ok()) << run.error().message;
  auto series = RunSeries::create(**run, outDir("run_series") / "series", "tets");
  ASSERT_TRUE(series.ok()) << series.error().message;
  for (int f = 0; f < 10; ++f) {
    ASSERT_TRUE((*run)->advance().ok());
    auto cost = series->addFrame(**run);
    ASSERT_TRUE(cost.ok()) << cost.error().message;
  }
  const auto entries = readPvd(series->series().pvdPath());
  ASSERT_EQ(entries.size(), 10u);
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName((outDir("run_series") / "series" / entries.back().second).c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  const std::size_t points = (*run)->mesh().positions.size();
  const std::size_t cells = (*run)->mesh().tets.size() + (*run)->mesh().triangles.size();
  ASSERT_EQ(std::size_t(grid->GetNumberOfPoints()), points);
  ASSERT_EQ(std::size_t(grid->GetNumberOfCells()), cells);
  EXPECT_EQ(grid->GetCellType(0), VTK_TETRA);
  EXPECT_EQ(grid->GetCellType(vtkIdType(cells - 1)), VTK_TRIANGLE);
  for (const char* name : kPointArrays) {
    vtkDataArray* a = grid->GetPointData()->GetArray(name);
    ASSERT_NE(a, nullptr) << name;
    EXPECT_EQ(std::size_t(a->GetNumberOfTuples()), points) << name;
  }
  // It falls: in the first frames the free vertices move down under gravity (later the
  // simulator's over-stretch recovery stops the barely pinned liver).
  vtkNew<vtkXMLUnstructuredGridReader> early;
  early->SetFileName((outDir("run_series") / "series" / entries[2].second).c_str());
  early->Update();
  double vz = 0.0;
  vtkDataArray* velocity = early->GetOutput()->GetPointData()->GetArray("velocity_mm_per_s");
  for (vtkIdType p = 0; p < velocity->GetNumberOfTuples(); ++p)
    vz += velocity->GetComponent(p, 2);
  EXPECT_LT(vz, 0.0);
}

TEST(PvdSeries, FramesOutOfTimeOrderAndBadNamesAreErrors) {
  auto bad = PvdSeries::create(outDir("pvd_bad"), "a/b");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message.find("file stem"), std::string::npos);
  auto s = scenario::loadScenario(test::writePokedGrid(outDir("pvd_bad") / "scenario", 7, 2.0, 10));
  ASSERT_TRUE(s.ok()) << s.error().message;
  auto mesh = mesh::loadMesh(s->mesh, {.requireUvs = true});
  ASSERT_TRUE(mesh.ok());
  auto loop = scene::OrganLoop::create(*s, std::move(*mesh));
  ASSERT_TRUE(loop.ok());
  auto series = PvdSeries::create(outDir("pvd_bad") / "series");
  ASSERT_TRUE(series.ok());
  ASSERT_TRUE(loop->advance().ok());
  const OrganSnapshot snap = snapshotOf(loop->run(), loop->surface());
  ASSERT_TRUE(series->addFrame(snap).ok());
  auto again = series->addFrame(snap);
  ASSERT_FALSE(again.ok());
  EXPECT_NE(again.error().message.find("time order"), std::string::npos) << again.error().message;
  EXPECT_EQ(series->frameCount(), 1u);
}

}  // namespace
}  // namespace tissue::inspect
