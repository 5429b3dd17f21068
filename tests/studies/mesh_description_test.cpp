// What a mesh file holds (studies/mesh_description.h): the data liver's surface and a one-tet
// volume, their figures equal to the loaders', and a missing file named in the error.
#include "tissue/studies/mesh_description.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tissue/mesh/load_mesh.h"

namespace tissue::studies {
namespace {

const std::filesystem::path kData = TISSUE_TEST_DATA_DIR;

TEST(MeshDescription, SurfaceFiguresAreTheLoadersAndScaleWithTheUnit) {
  const auto file = kData / "meshes" / "liver.obj";
  auto loaded = mesh::loadMesh(file, {.requireUvs = false});
  ASSERT_TRUE(loaded) << loaded.error().message;
  auto d = describeMeshFile(file, {});
  ASSERT_TRUE(d) << d.error().message;
  const auto j = nlohmann::json::parse(d->json);
  for (const char* key : {"vertices", "render_vertices", "faces", "has_uvs", "bbox_min", "bbox_max", "units",
                          "dropped_zero_area_faces", "dropped_line_elements", "warnings"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_FALSE(j.contains("kind"));
  EXPECT_EQ(j["vertices"], loaded->geometricVertexCount);
  EXPECT_EQ(j["render_vertices"], loaded->positions.size());
  EXPECT_EQ(j["faces"], loaded->triangles.size());
  EXPECT_EQ(j["has_uvs"], true);
  EXPECT_EQ(j["units"], "mm");
  EXPECT_EQ(j["warnings"].size(), d->warnings.size());
  for (int a = 0; a < 3; ++a)
    EXPECT_LT(j["bbox_min"][a].get<double>(), j["bbox_max"][a].get<double>());
  // Twice the unit: the box twice as large, the counts the same.
  auto twice = describeMeshFile(file, {.scaleToMm = 2.0f});
  ASSERT_TRUE(twice) << twice.error().message;
  const auto t = nlohmann::json::parse(twice->json);
  EXPECT_EQ(t["faces"], j["faces"]);
  for (int a = 0; a < 3; ++a)
    EXPECT_NEAR(t["bbox_max"][a].get<double>(), 2.0 * j["bbox_max"][a].get<double>(), 1e-3);
}

TEST(MeshDescription, OneTetVolumeHasItsAnalyticVolume) {
  const std::filesystem::path dir = std::filesystem::path(TISSUE_TEST_OUTPUT_DIR) / "mesh_description";
  std::filesystem::create_directories(dir);
  // Gmsh, which both builds read (the VTK readers exist only with TISSUE_WITH_VTK=ON).
  const auto file = dir / "one_tet.msh";
  std::ofstream(file) << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 10 0 0\n3 0 10 0\n"
                         "4 0 0 10\n$EndNodes\n$Elements\n1\n1 4 2 0 1 1 2 3 4\n$EndElements\n";
  auto d = describeMeshFile(file, {});
  ASSERT_TRUE(d) << d.error().message;
  const auto j = nlohmann::json::parse(d->json);
  EXPECT_EQ(j["kind"], "tetrahedral volume");
  EXPECT_EQ(j["vertices"], 4);
  EXPECT_EQ(j["tets"], 1);
  EXPECT_EQ(j["boundary_triangles"], 4);
  EXPECT_NEAR(j["volume_mm3"].get<double>(), 1000.0 / 6.0, 1e-6);  // a b c / 6
  for (int a = 0; a < 3; ++a) {
    EXPECT_DOUBLE_EQ(j["bbox_min"][a].get<double>(), 0.0);
    EXPECT_DOUBLE_EQ(j["bbox_max"][a].get<double>(), 10.0);
  }
  EXPECT_EQ(j["reoriented_tets"], 0);
}

TEST(MeshDescription, MissingFileIsNamed) {
  auto d = describeMeshFile("no/such/organ.obj", {});
  ASSERT_FALSE(d);
  EXPECT_NE(d.error().message.find("no/such/organ.obj"), std::string::npos) << d.error().message;
}

}  // namespace
}  // namespace tissue::studies
