// The Gmsh reader on the three ASCII versions: the same two tets, a triangle ignored.
#include <gtest/gtest.h>

#include <cmath>

#include "test_files.h"
#include "tissue/volume/tet_mesh.h"

namespace tissue::volume {
namespace {

using test::writeTestFile;

// Tets (1-based node tags): (1,2,3,4) positive; (2,4,3,5) written inverted (negative volume).
void expectTwoTets(const std::filesystem::path& file) {
  TetLoadReport report;
  auto mesh = loadTetMesh(file, {}, &report);
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  EXPECT_EQ(mesh->positions.size(), 5u);
  ASSERT_EQ(mesh->tets.size(), 2u);
  EXPECT_EQ(report.ignoredCells, 1u);  // the triangle
  for (const Tet& t : mesh->tets)
    EXPECT_GT(signedTetVolume(mesh->positions, t), 0.0);
  // (0,0,0),(1,0,0),(0,1,0),(0,0,1): 1/6; (1,0,0),(0,1,0),(0,0,1),(1,1,1): |det| / 6 = 2/6.
  EXPECT_NEAR(totalVolume(*mesh), 0.5, 1e-12);
  EXPECT_EQ(report.reorientedTets, 1u);  // the second tet is written inverted
  EXPECT_EQ(mesh->positions[4], (Float3{1, 1, 1}));
}

TEST(GmshReader, Version1) {
  expectTwoTets(writeTestFile("v1.msh",
                              "$NOD\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n$ENDNOD\n"
                              "$ELM\n3\n1 2 1 1 3 1 2 3\n2 4 1 1 4 1 2 3 4\n3 4 1 1 4 2 4 3 5\n$ENDELM\n"));
}

TEST(GmshReader, Version2Ascii) {
  expectTwoTets(writeTestFile("v2.msh",
                              "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
                              "$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n$EndNodes\n"
                              "$Elements\n3\n1 2 2 0 1 1 2 3\n2 4 2 0 1 1 2 3 4\n3 4 2 0 1 2 4 3 5\n"
                              "$EndElements\n"));
}

TEST(GmshReader, Version41AsciiWithSparseTags) {
  // Node tags 10..50 (not 1..5) and two entity blocks of nodes.
  expectTwoTets(writeTestFile("v41.msh",
                              "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
                              "$Entities\n0 0 0 1\n1 0 0 0 1 1 1 0 0\n$EndEntities\n"
                              "$Nodes\n2 5 10 50\n3 1 0 3\n10\n20\n30\n0 0 0\n1 0 0\n0 1 0\n"
                              "3 1 0 2\n40\n50\n0 0 1\n1 1 1\n$EndNodes\n"
                              "$Elements\n2 3 1 3\n2 1 2 1\n1 10 20 30\n3 1 4 2\n2 10 20 30 40\n"
                              "3 20 40 30 50\n$EndElements\n"));
}

TEST(GmshReader, BinaryIsRefusedWithAFix) {
  auto mesh = loadTetMesh(writeTestFile("binary.msh", "$MeshFormat\n4.1 1 8\n$EndMeshFormat\n"));
  ASSERT_FALSE(mesh.ok());
  EXPECT_NE(mesh.error().message.find("binary"), std::string::npos) << mesh.error().message;
  EXPECT_NE(mesh.error().message.find("ASCII"), std::string::npos);
}

TEST(GmshReader, UnknownNodeTagIsNamed) {
  auto mesh = loadTetMesh(writeTestFile("badtag.msh",
                                        "$NOD\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$ENDNOD\n"
                                        "$ELM\n1\n1 4 1 1 4 1 2 3 9\n$ENDELM\n"));
  ASSERT_FALSE(mesh.ok());
  EXPECT_NE(mesh.error().message.find("element 1 refers to node tag 9"), std::string::npos)
      << mesh.error().message;
  EXPECT_NE(mesh.error().message.find("badtag.msh:"), std::string::npos);
}

}  // namespace
}  // namespace tissue::volume
