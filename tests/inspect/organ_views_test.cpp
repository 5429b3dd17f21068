// The inspection views of a simulated organ: the fields are physically right (strain 0 at rest,
// the contact forces sum to the tool's, plane residual 0 on a plane, no seam flips on a seamless
// grid, texture stretch 1 on a uniform map), and every view writes a non-blank PNG with a colour
// bar and a .vtp holding its arrays at the right sizes.
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include <cmath>
#include <set>

#include "../scene/loop_fixture.h"
#include "tissue/core/image.h"
#include "tissue/core/vec_math.h"
#include "tissue/inspect/inspection_views.h"
#include "tissue/mesh/load_mesh.h"
#include "tissue/scene/organ_loop.h"
#include "tissue/scene/scene.h"

namespace tissue::inspect {
namespace {

namespace fs = std::filesystem;

fs::path outDir(const char* name) {
  return fs::path(TISSUE_TEST_OUTPUT_DIR) / "inspect" / name;
}

Result<scene::OrganLoop> pokedGrid(const char* name, int frames = 200) {
  const fs::path file = test::writePokedGrid(outDir(name), 15, 2.0, frames);
  auto s = scenario::loadScenario(file);
  if (!s) return s.error();
  auto mesh = mesh::loadMesh(s->mesh, {.requireUvs = true});
  if (!mesh) return mesh.error();
  return scene::OrganLoop::create(*s, std::move(*mesh));
}

TEST(OrganSnapshot, AtRestStrainIsZeroStretchOnePlanesFlatTextureUniform) {
  auto loop = pokedGrid("rest");
  ASSERT_TRUE(loop.ok()) << loop.error().message;
  const OrganSnapshot s = snapshotOf(loop->run(), loop->surface());
  ASSERT_EQ(s.nodes.strain.size(), s.nodes.springs.size());
  ASSERT_GT(s.nodes.springs.size(), 15u * 15u);
  for (float e : s.nodes.strain)
    EXPECT_NEAR(e, 0.0f, 1e-6f);
  for (float l : s.surface.stretch)
    EXPECT_NEAR(l, 1.0f, 1e-6f);
  for (float r : s.surface.planeResidualMm)
    EXPECT_NEAR(r, 0.0f, 1e-5f);  // a plane's neighbours lie on its plane
  for (float t : s.render.textureStretch)
    EXPECT_NEAR(t, 1.0f, 1e-4f);  // a uniform UV map: every triangle has the mean density
  for (float f : s.render.handednessFlip)
    EXPECT_EQ(f, 0.0f);  // no seams
  for (const Float3& f : s.surface.contactForceN)
    EXPECT_EQ(length(f), 0.0f);  // the tool starts above the grid
}

TEST(OrganSnapshot, ContactForcesSumToTheToolsReportedForceWhileTheToolHolds) {
  // The default scenario (the lattice liver, symplectic Euler): the tool reaches 12 mm deep at
  // 3.0 s and holds until 3.5 s; at frame 200 (3.33 s) the tissue rests against it, so the
  // quasi-static reactions equal the instrument's momentum force. (An implicit-Euler organ can
  // "rest" with residual forces its inexact solve leaves: the sum then is not the tool's force.)
  const fs::path scenarioFile = fs::path(TISSUE_TEST_DATA_DIR) / "scenarios" / "liver_poke_grasp.json";
  auto organ = scene::loadSimulatedOrgan({.scenario = scenarioFile});
  ASSERT_TRUE(organ.ok()) << organ.error().message;
  auto loop = scene::OrganLoop::create(organ->scenario, organ->assets.mesh, {.planes = organ->assets.planes});
  ASSERT_TRUE(loop.ok()) << loop.error().message;
  for (int f = 0; f < 200; ++f)
    ASSERT_TRUE(loop->advance().ok());
  const OrganSnapshot s = snapshotOf(loop->run(), loop->surface());
  Float3 sum{};
  std::uint32_t loaded = 0;
  for (std::size_t i = 0; i < s.surface.positions.size(); ++i) {
    const Float3 f = s.surface.contactForceN[i];
    sum = sum + f;
    if (length(f) == 0.0f) continue;
    ++loaded;  // only vertices on the tool carry a contact force
    EXPECT_LT(length(s.surface.positions[i] - s.tool.centreMm) - s.tool.radiusMm, 0.02f * s.tool.radiusMm);
  }
  const Float3 reported = s.tool.forceN;
  EXPECT_GT(loaded, 0u);
  EXPECT_GT(reported.z, 0.5f);  // N: the liver pushes the tool up
  EXPECT_LT(length(sum - reported), 0.03f * length(reported))
      << "sum " << sum.x << " " << sum.y << " " << sum.z << " reported " << reported.x << " " << reported.y
      << " " << reported.z;
}

TEST(OrganFields, HandednessFlipsMarkBothCopiesOfAMirroredSeamVertex) {
  const std::vector<Float4> tangents{{1, 0, 0, 1}, {1, 0, 0, -1}, {1, 0, 0, 1}, {1, 0, 0, 1}};
  const std::vector<std::uint32_t> geometric{0, 0, 1, 1};
  const auto flips = handednessFlips(tangents, geometric);
  EXPECT_EQ(flips, (std::vector<float>{1, 1, 0, 0}));
}

TEST(OrganFields, PlaneResidualIsTheRmsDistanceFromThePlane) {
  // Vertex 0's plane z = 0 (normal +z, d = 0); neighbours at z = 0, 1, -1: RMS sqrt(2/3) mm.
  const std::vector<Float3> p{{0, 0, 0}, {1, 0, 1}, {0, 1, -1}};
  const std::vector<Float3> n{{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  const std::vector<Float4> planes{{0, 0, 1, 0}, {0, 0, 1, 0}, {0, 0, 1, 0}};
  const std::vector<std::uint32_t> offsets{0, 3, 3, 3}, hood{0, 1, 2};
  const auto r = planeResidualMm(p, n, planes, offsets, hood);
  EXPECT_NEAR(r[0], std::sqrt(2.0f / 3.0f), 1e-6f);
  EXPECT_EQ(r[1], 0.0f);
}

/// Non-background pixels of the image left of the colour bar, and distinct colours down the bar.
void expectImageWithColourBar(const fs::path& png, const ViewSettings& settings) {
  auto image = readImage(png, 3);
  ASSERT_TRUE(image.ok()) << image.error().message;
  ASSERT_EQ(image->width, settings.widthPx);
  ASSERT_EQ(image->height, settings.heightPx);
  int drawn = 0;
  for (int y = 0; y < image->height; ++y)
    for (int x = 0; x < image->width * 8 / 10; ++x) {
      const auto* p = image->at(x, y);
      if (p[0] < 235 || p[1] < 235 || p[2] < 235) ++drawn;
    }
  EXPECT_GT(drawn, image->width * image->height / 50) << png << ": the view looks blank";
  // The bar: a column through its strip (x 0.84..0.89 of the width) shows the map's gradient.
  std::set<int> colours;
  const int x = int(0.865 * image->width);
  for (int y = image->height / 5; y < image->height * 4 / 5; ++y) {
    const auto* p = image->at(x, y);
    colours.insert(p[0] << 16 | p[1] << 8 | p[2]);
  }
  EXPECT_GT(colours.size(), 40u) << png << ": no colour bar at x = " << x;
}

TEST(InspectionViews, EveryViewWritesAnImageWithAColourBarAndItsArrays) {
  auto loop = pokedGrid("views");
  ASSERT_TRUE(loop.ok()) << loop.error().message;
  for (int f = 0; f < 45; ++f)
    ASSERT_TRUE(loop->advance().ok());
  const OrganSnapshot s = snapshotOf(loop->run(), loop->surface());
  const ViewSettings settings{.widthPx = 640, .heightPx = 480};
  const fs::path dir = outDir("views") / "out";
  fs::remove_all(dir);
  auto written = writeInspectionViews(s, dir, settings);
  ASSERT_TRUE(written.ok()) << written.error().message;
  ASSERT_EQ(written->size(), std::size(kInspectionViews));
  // What each .vtp must hold: (array, point data?, tuples, components).
  struct Expect {
    const char* array;
    bool point;
    std::size_t tuples;
    int components;
  };
  const std::size_t n = s.nodes.positions.size(), g = s.surface.positions.size(),
                    r = s.render.positions.size();
  const std::vector<std::vector<Expect>> expected{
      {{"strain", false, s.nodes.springs.size(), 1},
       {"stretch", true, n, 1},
       {"velocity_mm_per_s", true, n, 3}},
      {{"stretch", true, g, 1}, {"velocity_mm_per_s", true, g, 3}},
      {{"contact_force_N", true, g, 3}, {"contact_force_magnitude_N", true, g, 1}},
      {{"plane_normal", true, g, 3}, {"plane_offset_mm", true, g, 1}, {"plane_residual_mm", true, g, 1}},
      {{"tangent", true, r, 4},
       {"bitangent", true, r, 3},
       {"normal", true, r, 3},
       {"handedness", true, r, 1},
       {"seam_flip", true, r, 1}},
      {{"texture_stretch", false, s.render.triangles.size(), 1}, {"uv", true, r, 2}}};
  for (std::size_t v = 0; v < written->size(); ++v) {
    const WrittenView& w = (*written)[v];
    SCOPED_TRACE(w.name);
    EXPECT_EQ(w.name, viewName(kInspectionViews[v]));
    expectImageWithColourBar(w.png, settings);
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(w.data.c_str());
    reader->Update();
    vtkPolyData* poly = reader->GetOutput();
    ASSERT_GT(poly->GetNumberOfPoints(), 0);
    for (const Expect& e : expected[v]) {
      vtkDataArray* a =
          e.point ? poly->GetPointData()->GetArray(e.array) : poly->GetCellData()->GetArray(e.array);
      ASSERT_NE(a, nullptr) << e.array;
      EXPECT_EQ(std::size_t(a->GetNumberOfTuples()), e.tuples) << e.array;
      EXPECT_EQ(a->GetNumberOfComponents(), e.components) << e.array;
    }
  }
}

TEST(InspectionViews, TheTruthErrorHookDrawsAGivenMapAndRejectsAWrongSize) {
  auto loop = pokedGrid("truth");
  ASSERT_TRUE(loop.ok()) << loop.error().message;
  const OrganSnapshot s = snapshotOf(loop->run(), loop->surface());
  TruthErrorMap map{{}, "relative luminance error", "unitless"};
  map.perRenderVertex.resize(s.render.positions.size() - 1);
  auto bad = writeTruthErrorView(s, map, outDir("truth") / "out");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message.find("render vertices"), std::string::npos) << bad.error().message;
  map.perRenderVertex.clear();
  for (const Float3& p : s.render.positions)
    map.perRenderVertex.push_back(0.01f * p.x);
  const ViewSettings settings{.widthPx = 480, .heightPx = 360};
  auto good = writeTruthErrorView(s, map, outDir("truth") / "out", settings);
  ASSERT_TRUE(good.ok()) << good.error().message;
  expectImageWithColourBar(good->png, settings);
}

TEST(InspectionViews, BadSettingsGiveOneClearError) {
  auto loop = pokedGrid("bad");
  ASSERT_TRUE(loop.ok()) << loop.error().message;
  const OrganSnapshot s = snapshotOf(loop->run(), loop->surface());
  auto w = writeInspectionView(s, InspectionView::PlaneFit, outDir("bad"), {.widthPx = 10});
  ASSERT_FALSE(w.ok());
  EXPECT_NE(w.error().message.find("64..8192"), std::string::npos);
  OrganSnapshot broken = s;
  broken.surface.planeResidualMm.pop_back();
  auto b = writeInspectionView(broken, InspectionView::PlaneFit, outDir("bad"));
  ASSERT_FALSE(b.ok());
  EXPECT_NE(b.error().message.find("snapshotOf"), std::string::npos);
}

}  // namespace
}  // namespace tissue::inspect
