// Loaders: every shared mesh in a supported format loads; malformed files give one clear
// error naming the file and the element or line.
#include <gtest/gtest.h>

#include <filesystem>

#include "test_meshes.h"
#include "tissue/mesh/load_mesh.h"

namespace tissue::mesh {
namespace {

using test::writeTestFile;

std::string loadError(const std::filesystem::path& path, LoadOptions options = {}) {
  auto r = loadMesh(path, options);
  EXPECT_FALSE(r.ok()) << path;
  return r.ok() ? std::string() : r.error().message;
}

TEST(LoadMesh, EverySharedMeshInASupportedFormatLoads) {
  const std::filesystem::path dir = std::filesystem::path(TISSUE_TEST_SHARED_DIR) / "meshes";
  if (!std::filesystem::exists(dir)) GTEST_FAIL() << "no shared meshes at " << dir;
  int loaded = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const auto ext = entry.path().extension().string();
    if (ext != ".obj" && ext != ".off" && ext != ".stl" && ext != ".ply") continue;
    LoadReport report;
    auto mesh = loadMesh(entry.path(), {}, &report);
    ASSERT_TRUE(mesh.ok()) << mesh.error().message;
    EXPECT_GT(mesh->triangleCount(), 100u) << entry.path();
    EXPECT_EQ(mesh->geometricIndex.size(), mesh->positions.size());
    EXPECT_TRUE(validateMesh(*mesh, entry.path().string()).ok());
    ++loaded;
  }
  EXPECT_GE(loaded, 10);
}

TEST(LoadMesh, KeepsUvsAndSplitsSeams) {
  // Two triangles sharing an edge whose UVs differ on the two sides: a seam.
  const auto path = writeTestFile("seam.obj",
                                  "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                  "vt 0 0\nvt 0.5 0\nvt 0.5 0.5\nvt 0.6 0.5\nvt 0.6 0\nvt 1 1\n"
                                  "f 1/1 2/2 3/3\nf 1/5 3/4 4/6\n");
  auto mesh = loadMesh(path, {.requireUvs = true});
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  EXPECT_EQ(mesh->geometricVertexCount, 4u);
  EXPECT_EQ(mesh->positions.size(), 6u);  // vertices 1 and 3 are split by the seam
  EXPECT_TRUE(mesh->hasUvs());
}

TEST(LoadMesh, ScalesToMillimetres) {
  const auto path = writeTestFile("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 2 0\nf 1 2 3\n");
  auto mesh = loadMesh(path, {.scaleToMm = 25.0f});
  ASSERT_TRUE(mesh.ok());
  EXPECT_FLOAT_EQ(mesh->positions[2].y, 50.0f);
}

TEST(LoadMesh, RejectsNanWithLine) {
  const auto msg = loadError(writeTestFile("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n"));
  EXPECT_NE(msg.find("nan.obj"), std::string::npos) << msg;
  EXPECT_NE(msg.find("vertex 2"), std::string::npos) << msg;
  EXPECT_NE(msg.find("non-finite"), std::string::npos) << msg;
}

TEST(LoadMesh, RejectsInfinity) {
  const auto msg = loadError(writeTestFile("inf.obj", "v 0 0 0\nv 1 0 0\nv 0 inf 0\nf 1 2 3\n"));
  EXPECT_NE(msg.find("vertex 3"), std::string::npos) << msg;
}

TEST(LoadMesh, RejectsOutOfRangeIndexWithLine) {
  const auto msg = loadError(writeTestFile("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 9\n"));
  EXPECT_NE(msg.find("range.obj:5"), std::string::npos) << msg;
  EXPECT_NE(msg.find("'9'"), std::string::npos) << msg;
}

TEST(LoadMesh, RejectsOutOfRangeIndexInOff) {
  const auto msg = loadError(writeTestFile("range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"));
  EXPECT_NE(msg.find("range.off"), std::string::npos) << msg;
}

TEST(LoadMesh, RejectsRepeatedVertexInFace) {
  const auto msg = loadError(writeTestFile("repeat.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2\n"));
  EXPECT_NE(msg.find("face 1 (line 4)"), std::string::npos) << msg;
  EXPECT_NE(msg.find("degenerate"), std::string::npos) << msg;
}

TEST(LoadMesh, ZeroAreaFaceIsDroppedLenientlyAndRejectedStrictly) {
  const auto path = writeTestFile("sliver.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 4 2\n");
  LoadReport report;
  auto mesh = loadMesh(path, {}, &report);
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  EXPECT_EQ(mesh->triangleCount(), 1u);
  EXPECT_EQ(report.droppedZeroAreaFaces, 1u);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_NE(report.warnings[0].find("face 2 (line 6)"), std::string::npos) << report.warnings[0];
  const auto msg = loadError(path, {.strict = true});
  EXPECT_NE(msg.find("face 2 (line 6)"), std::string::npos) << msg;
  EXPECT_NE(msg.find("zero area"), std::string::npos) << msg;
}

TEST(LoadMesh, RejectsEdgeSharedByThreeFaces) {
  const auto msg = loadError(writeTestFile("fin.obj",
                                           "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\n"
                                           "f 1 2 3\nf 2 1 4\nf 1 2 5\n"));
  EXPECT_NE(msg.find("non-manifold"), std::string::npos) << msg;
  EXPECT_NE(msg.find("face 3 (line 8)"), std::string::npos) << msg;
}

TEST(LoadMesh, RejectsInconsistentOrientation) {
  const auto msg =
      loadError(writeTestFile("flip.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 3 4\n"));
  EXPECT_NE(msg.find("oriented against"), std::string::npos) << msg;
}

TEST(LoadMesh, RejectsTwoSheetsTouchingAtAVertex) {
  // Two triangles (a bow tie) sharing only vertex 1: each is fine, together not a 2-manifold.
  const auto msg =
      loadError(writeTestFile("bowtie.obj",
                              "v 0 0 0\nv 1 0 0\nv 1 1 0\nv -1 0 0\nv -1 -1 0\nv 0 0 1\nv 1 0 1\n"
                              "f 1 2 3\nf 1 4 5\nf 1 3 6\nf 1 6 7\nf 1 7 2\n"));
  EXPECT_NE(msg.find("non-manifold"), std::string::npos) << msg;
}

TEST(LoadMesh, MissingUvsWhenRequired) {
  const auto msg =
      loadError(writeTestFile("nouv.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), {.requireUvs = true});
  EXPECT_NE(msg.find("no texture coordinates"), std::string::npos) << msg;
}

TEST(LoadMesh, PartialUvsAreAnError) {
  const auto msg = loadError(writeTestFile("partuv.obj",
                                           "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                                           "f 1/1 2/2 3/3\nf 2 4 3\n"));
  EXPECT_NE(msg.find("face 2"), std::string::npos) << msg;
}

const char* kQuadPly =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
    "property float u\nproperty float v\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0 0 0\n1 0 0 1 0\n1 1 0 1 1\n0 1 0 0 1\n3 0 1 2\n3 0 2 3\n";

TEST(LoadMesh, PlyKeepsPerVertexUvs) {
  auto mesh = loadMesh(writeTestFile("quad.ply", kQuadPly), {.requireUvs = true});
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  EXPECT_EQ(mesh->triangleCount(), 2u);
  ASSERT_TRUE(mesh->hasUvs());
  EXPECT_EQ(mesh->uvs[mesh->triangles[0][2]], (Float2{1, 1}));
}

TEST(LoadMesh, NonFiniteNumbersInTextPlyOffStlNameTheLine) {
  std::string ply = kQuadPly;
  ply.replace(ply.find("1 1 0 1 1"), 9, "1 nan 0 1 1");
  EXPECT_NE(loadError(writeTestFile("nan.ply", ply)).find("nan.ply:14: non-finite"), std::string::npos);
  EXPECT_NE(
      loadError(writeTestFile("nan.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 -inf 0\n3 0 1 2\n")).find("nan.off:5"),
      std::string::npos);
  const auto stl =
      "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 NaN 0\n"
      "endloop\nendfacet\nendsolid t\n";
  EXPECT_NE(loadError(writeTestFile("nan.stl", stl)).find("nan.stl:6"), std::string::npos);
}

TEST(LoadMesh, OutOfRangeIndexInPly) {
  std::string ply = kQuadPly;
  ply.replace(ply.find("3 0 2 3"), 7, "3 0 2 9");
  const auto msg = loadError(writeTestFile("range.ply", ply));
  EXPECT_NE(msg.find("face 2 refers to vertex 10"), std::string::npos) << msg;
}

TEST(LoadMesh, UnsupportedExtensionAndMissingFile) {
  EXPECT_NE(loadError(writeTestFile("mesh.xyz", "1 2 3\n")).find("unsupported extension"), std::string::npos);
  EXPECT_NE(loadError("/nonexistent/mesh.obj").find("no such file"), std::string::npos);
}

TEST(LoadMesh, BadNumberNamesTheLine) {
  const auto msg = loadError(writeTestFile("garbage.obj", "v 0 0 0\nv 1 0 zero\nv 0 1 0\nf 1 2 3\n"));
  EXPECT_NE(msg.find("garbage.obj:2"), std::string::npos) << msg;
}

TEST(LoadMesh, WriteObjRoundTrips) {
  const auto path = writeTestFile("seam2.obj",
                                  "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                  "vt 0 0\nvt 0.5 0\nvt 0.5 0.5\nvt 0.6 0.5\nvt 0.6 0\nvt 1 1\n"
                                  "f 1/1 2/2 3/3\nf 1/5 3/4 4/6\n");
  auto a = loadMesh(path);
  ASSERT_TRUE(a.ok());
  const auto out = std::filesystem::path(TISSUE_TEST_OUTPUT_DIR) / "mesh" / "roundtrip.obj";
  ASSERT_TRUE(writeObj(out, *a).ok());
  auto b = loadMesh(out);
  ASSERT_TRUE(b.ok()) << b.error().message;
  EXPECT_EQ(a->positions, b->positions);
  EXPECT_EQ(a->uvs, b->uvs);
  EXPECT_EQ(a->triangles, b->triangles);
  EXPECT_EQ(a->geometricIndex, b->geometricIndex);
}

}  // namespace
}  // namespace tissue::mesh
