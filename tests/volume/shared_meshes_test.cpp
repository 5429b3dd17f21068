// The three shared volume meshes load with the counts their headers state (read here a second,
// independent way), positive tets, and a total volume equal to the volume their boundary encloses.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "tissue/volume/tet_mesh.h"

namespace tissue::volume {
namespace {

const std::filesystem::path kMeshes = std::filesystem::path(TISSUE_TEST_SHARED_DIR) / "meshes";

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Counts stated by the file, read independently of the loader: vertices and tets.
struct HeaderCounts {
  std::size_t vertices = 0, tets = 0, cells = 0;
};

/// Legacy VTK: "POINTS n", "CELLS n", and the tets among CELL_TYPES (type 10).
HeaderCounts legacyVtkCounts(const std::string& text) {
  HeaderCounts c;
  std::smatch m;
  std::regex_search(text, m, std::regex(R"(POINTS\s+(\d+))"));
  c.vertices = std::stoul(m[1]);
  std::regex_search(text, m, std::regex(R"(CELLS\s+(\d+))"));
  c.cells = std::stoul(m[1]);
  std::istringstream types(text.substr(text.find("CELL_TYPES")));
  std::string word;
  std::size_t n = 0;
  types >> word >> n;
  for (std::size_t k = 0; k < n; ++k) {
    int type = 0;
    types >> type;
    c.tets += type == 10 ? 1 : 0;
  }
  return c;
}

/// VTK XML: NumberOfPoints, NumberOfCells, and the 10s of the "types" array.
HeaderCounts vtuCounts(const std::string& text) {
  HeaderCounts c;
  std::smatch m;
  std::regex_search(text, m, std::regex(R"(NumberOfPoints="(\d+)\")"));
  c.vertices = std::stoul(m[1]);
  std::regex_search(text, m, std::regex(R"(NumberOfCells="(\d+)\")"));
  c.cells = std::stoul(m[1]);
  const auto start = text.find('>', text.find("Name=\"types\"")) + 1;
  std::istringstream types(text.substr(start, text.find("</DataArray>", start) - start));
  for (int type = 0; types >> type;)
    c.tets += type == 10 ? 1 : 0;
  return c;
}

/// Gmsh v1: the counts after $NOD and $ELM, tets = elements of type 4 (second column).
HeaderCounts gmshV1Counts(const std::string& text) {
  HeaderCounts c;
  std::istringstream nod(text.substr(text.find("$NOD") + 4));
  nod >> c.vertices;
  std::istringstream elm(text.substr(text.find("$ELM") + 4));
  elm >> c.cells;
  std::string line;
  std::getline(elm, line);
  for (std::size_t k = 0; k < c.cells && std::getline(elm, line); ++k) {
    std::istringstream fields(line);
    int number = 0, type = 0;
    fields >> number >> type;
    c.tets += type == 4 ? 1 : 0;
  }
  return c;
}

void expectSound(const std::filesystem::path& file, const HeaderCounts& header) {
  TetLoadReport report;
  auto mesh = loadTetMesh(file, {}, &report);
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  EXPECT_EQ(mesh->positions.size(), header.vertices);
  EXPECT_EQ(mesh->tets.size(), header.tets);
  EXPECT_EQ(report.ignoredCells, header.cells - header.tets);
  EXPECT_GT(header.tets, 100u);  // plausible: a real organ volume

  // Every tet positive, and the total equals the volume the boundary surface encloses.
  double smallest = 1e300;
  for (const Tet& t : mesh->tets)
    smallest = std::min(smallest, signedTetVolume(mesh->positions, t));
  EXPECT_GT(smallest, 0.0);
  const double total = totalVolume(*mesh);
  const auto boundary = boundaryTriangles(*mesh);
  EXPECT_GT(boundary.size(), 0u);
  EXPECT_NEAR(enclosedVolume(mesh->positions, boundary), total, 1e-9 * total);
}

TEST(SharedVolumeMeshes, LiverMshLoadsWithItsHeaderCounts) {
  const auto file = kMeshes / "liver.msh";
  if (!std::filesystem::exists(file)) GTEST_FAIL() << "no " << file;
  expectSound(file, gmshV1Counts(slurp(file)));
}

TEST(SharedVolumeMeshes, LiverVtkLoadsWithItsHeaderCounts) {
  const auto file = kMeshes / "liver_tets.vtk";
  if (!std::filesystem::exists(file)) GTEST_FAIL() << "no " << file;
  expectSound(file, legacyVtkCounts(slurp(file)));
}

TEST(SharedVolumeMeshes, TongueVtuLoadsWithItsHeaderCounts) {
  const auto file = kMeshes / "volumetricTongue.vtu";
  if (!std::filesystem::exists(file)) GTEST_FAIL() << "no " << file;
  expectSound(file, vtuCounts(slurp(file)));
}

TEST(SharedVolumeMeshes, GmshAndVtkReadersAgreeOnTheSameLiver) {
  // liver_tets.vtk is liver.msh converted with the node order kept: two readers, one mesh.
  const auto msh = kMeshes / "liver.msh", vtk = kMeshes / "liver_tets.vtk";
  if (!std::filesystem::exists(msh) || !std::filesystem::exists(vtk)) GTEST_FAIL() << "no shared livers";
  auto a = loadTetMesh(msh), b = loadTetMesh(vtk);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(a->positions, b->positions);
  EXPECT_EQ(a->tets, b->tets);
}

}  // namespace
}  // namespace tissue::volume
