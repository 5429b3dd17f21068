// The volume module built without VTK (TISSUE_WITH_VTK=OFF, built only then): .vtk and .vtu files
// are one Error that names the file and says how to convert; Gmsh .msh still loads, validated,
// with its boundary and volumes.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "test_files.h"
#include "tissue/volume/tet_mesh.h"

namespace tissue::volume {
namespace {

using test::writeTestFile;

void expectBuiltWithoutVtk(const std::string& name, const std::string& text) {
  const auto path = writeTestFile(name, text);
  EXPECT_TRUE(isTetMeshPath(path)) << "a volume path, even when its reader is not built";
  auto mesh = loadTetMesh(path);
  ASSERT_FALSE(mesh.ok()) << name << " loaded without VTK";
  const std::string& m = mesh.error().message;
  EXPECT_NE(m.find(name), std::string::npos) << m;
  EXPECT_NE(m.find("built without VTK (TISSUE_WITH_VTK=OFF); convert to Gmsh .msh"), std::string::npos) << m;
}

TEST(VolumeWithoutVtk, LegacyVtkIsOneErrorThatSaysHowToConvert) {
  expectBuiltWithoutVtk("novtk.vtk",
                        "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 5 double\n" +
                            std::string(test::kTwoTetPoints) + "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n");
}

TEST(VolumeWithoutVtk, VtuIsOneErrorThatSaysHowToConvert) {
  expectBuiltWithoutVtk("novtk.vtu", "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\"/>\n");
}

TEST(VolumeWithoutVtk, GmshStillLoadsWithItsBoundary) {
  // The two tets of kTwoTetPoints (Gmsh v2: element type 4 = 4-node tet).
  const auto path = writeTestFile("novtk.msh",
                                  "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n5\n1 0 0 0\n2 1 0 0\n"
                                  "3 0 1 0\n4 0 0 1\n5 1 1 1\n$EndNodes\n$Elements\n2\n"
                                  "1 4 2 0 1 1 2 3 4\n2 4 2 0 1 2 3 5 4\n$EndElements\n");
  auto mesh = loadTetMesh(path);
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  ASSERT_EQ(mesh->tets.size(), 2u);
  EXPECT_NEAR(totalVolume(*mesh), 0.5, 1e-12);
  const auto boundary = boundaryTriangles(*mesh);
  EXPECT_EQ(boundary.size(), 6u);  // 8 faces, the shared one inside
  EXPECT_NEAR(enclosedVolume(mesh->positions, boundary), 0.5, 1e-12);
}

TEST(VolumeWithoutVtk, SharedLiverMshLoads) {
  const auto file = std::filesystem::path(TISSUE_TEST_SHARED_DIR) / "meshes" / "liver.msh";
  if (!std::filesystem::exists(file)) GTEST_FAIL() << "no " << file;
  auto mesh = loadTetMesh(file);
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  EXPECT_GT(mesh->tets.size(), 100u);
  const double total = totalVolume(*mesh);
  EXPECT_NEAR(enclosedVolume(mesh->positions, boundaryTriangles(*mesh)), total, 1e-9 * total);
}

}  // namespace
}  // namespace tissue::volume
