// The inspect module built without VTK (TISSUE_WITH_VTK=OFF, built only then): the exports and
// charts are one Error each that names the file and the option, and write nothing.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "tissue/inspect/chart.h"
#include "tissue/inspect/vtk_export.h"

namespace tissue::inspect {
namespace {

const std::filesystem::path kDir = std::filesystem::path(TISSUE_TEST_OUTPUT_DIR) / "inspect-without-vtk";

void expectBuiltWithoutVtk(const Result<void>& r, const std::filesystem::path& path) {
  ASSERT_FALSE(r.ok()) << path << " written without VTK";
  EXPECT_NE(r.error().message.find(path.string()), std::string::npos) << r.error().message;
  EXPECT_NE(r.error().message.find("built without VTK (TISSUE_WITH_VTK=OFF)"), std::string::npos)
      << r.error().message;
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(InspectWithoutVtk, VtpExportIsOneError) {
  std::filesystem::create_directories(kDir);
  const auto path = kDir / "quad.vtp";
  std::filesystem::remove(path);
  const std::vector<Float3> p = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}};
  const std::vector<Triangle> t = {{0, 1, 2}};
  expectBuiltWithoutVtk(writeVtp(path, p, t, {fieldOf<Float3>("normal", std::span<const Float3>(p))}), path);
}

TEST(InspectWithoutVtk, ChartIsOneError) {
  std::filesystem::create_directories(kDir);
  const auto path = kDir / "chart.png";
  std::filesystem::remove(path);
  const ChartSeries series[] = {{"line", {1.0, 2.0}, {3.0, 4.0}, true}};
  expectBuiltWithoutVtk(writeLineChart(path, {.title = "t", .xLabel = "x (mm)", .yLabel = "y (mm)"}, series),
                        path);
}

}  // namespace
}  // namespace tissue::inspect
