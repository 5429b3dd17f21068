// The inspection views and the ParaView series built without VTK (TISSUE_WITH_VTK=OFF, built only
// then): the snapshot still computes (plain arrays), every image or file is one Error that names
// the option, and nothing is written.
#include <gtest/gtest.h>

#include <filesystem>

#include "../scene/loop_fixture.h"
#include "tissue/inspect/inspection_views.h"
#include "tissue/inspect/pvd_series.h"
#include "tissue/mesh/load_mesh.h"
#include "tissue/scene/organ_loop.h"

namespace tissue::inspect {
namespace {

namespace fs = std::filesystem;

TEST(InspectWithoutVtk, SnapshotComputesAndEveryWriteIsOneError) {
  const fs::path dir = fs::path(TISSUE_TEST_OUTPUT_DIR) / "inspect-without-vtk" / "views";
  fs::remove_all(dir);
  auto s = scenario::loadScenario(test::writePokedGrid(dir / "scenario", 7, 2.0, 5));
  ASSERT_TRUE(s.ok()) << s.error().message;
  auto mesh = mesh::loadMesh(s->mesh, {.requireUvs = true});
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  auto loop = scene::OrganLoop::create(*s, std::move(*mesh));
  ASSERT_TRUE(loop.ok()) << loop.error().message;
  const OrganSnapshot snap = snapshotOf(loop->run(), loop->surface());
  ASSERT_EQ(snap.nodes.strain.size(), snap.nodes.springs.size());
  for (float e : snap.nodes.strain)
    EXPECT_NEAR(e, 0.0f, 1e-6f);
  const auto expectOption = [](const std::string& message) {
    EXPECT_NE(message.find("built without VTK (TISSUE_WITH_VTK=OFF)"), std::string::npos) << message;
  };
  auto views = writeInspectionViews(snap, dir / "out");
  ASSERT_FALSE(views.ok());
  expectOption(views.error().message);
  auto one = writeInspectionView(snap, InspectionView::PlaneFit, dir / "out");
  ASSERT_FALSE(one.ok());
  expectOption(one.error().message);
  auto series = PvdSeries::create(dir / "pvd");
  ASSERT_FALSE(series.ok());
  expectOption(series.error().message);
  auto frame = writeOrganFrame(snap, dir / "frame");
  ASSERT_FALSE(frame.ok());
  expectOption(frame.error().message);
  EXPECT_FALSE(hasDisplay());
  EXPECT_FALSE(fs::exists(dir / "out"));
  EXPECT_FALSE(fs::exists(dir / "pvd"));
}

}  // namespace
}  // namespace tissue::inspect
