// Loaders: every shared mesh in a supported format loads; malformed files give one clear
// error naming the file and the element or line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

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
  ASSERT_EQ(report.warnings.size(), 2u);  // the sliver, and its vertex 4 that no face uses now
  EXPECT_NE(report.warnings[0].find("face 2 (line 6)"), std::string::npos) << report.warnings[0];
  EXPECT_NE(report.warnings[1].find("dropped 1 vertices that no face uses (the first is vertex 4)"),
            std::string::npos)
      << report.warnings[1];
  const auto msg = loadError(path, {.strict = true});
  EXPECT_NE(msg.find("face 2 (line 6)"), std::string::npos) << msg;
  EXPECT_NE(msg.find("zero area"), std::string::npos) << msg;
}

// The repairs of lenient loading (issue 14): each gives the repaired counts and one warning
// line naming the file; strict loading refuses the same file naming the face and the fix.
std::size_t warningsContaining(const LoadReport& report, const std::string& what) {
  return std::size_t(std::count_if(report.warnings.begin(), report.warnings.end(),
                                   [&](const std::string& w) { return w.find(what) != std::string::npos; }));
}

TEST(LoadMesh, EdgeSharedByThreeFacesIsSplitLenientlyAndRejectedStrictly) {
  const auto path = writeTestFile("fin.obj",
                                  "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\n"
                                  "f 1 2 3\nf 2 1 4\nf 1 2 5\n");
  const auto msg = loadError(path, {.strict = true});
  EXPECT_NE(msg.find("non-manifold"), std::string::npos) << msg;
  EXPECT_NE(msg.find("face 3 (line 8)"), std::string::npos) << msg;
  LoadReport report;
  auto mesh = loadMesh(path, {}, &report);
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  EXPECT_EQ(report.splitNonManifoldEdges, 1u);
  EXPECT_EQ(mesh->triangleCount(), 3u);
  EXPECT_EQ(mesh->geometricVertexCount, 7u);  // the third face got its own copies of 1 and 2
  EXPECT_EQ(warningsContaining(report, "fin.obj: split 1 non-manifold edges"), 1u);
  EXPECT_EQ(report.warnings.size(), 1u);
  EXPECT_TRUE(validateMesh(*mesh, "fin").ok());
  // The copies stand for the file's vertices 1 and 2 (0-based 0 and 1).
  const auto& src = mesh->geometricSourceIndex;
  EXPECT_EQ(std::count(src.begin(), src.end(), 0u), 2);
  EXPECT_EQ(std::count(src.begin(), src.end(), 1u), 2);
}

TEST(LoadMesh, MisorientedFaceIsFlippedLenientlyAndRejectedStrictly) {
  // A strip of three faces; the middle one runs its shared edges the wrong way.
  const auto path = writeTestFile("flip.obj",
                                  "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\n"
                                  "f 1 2 3\nf 2 3 4\nf 2 5 4\n");
  EXPECT_NE(loadError(path, {.strict = true}).find("oriented against"), std::string::npos);
  LoadReport report;
  auto mesh = loadMesh(path, {}, &report);
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  EXPECT_EQ(report.flippedFaces, 1u);
  EXPECT_EQ(warningsContaining(report, "flip.obj: flipped 1 faces"), 1u);
  EXPECT_EQ(report.warnings.size(), 1u);
  // All three now face +z, as the majority did.
  for (const auto& t : mesh->triangles) {
    const Float3 a = mesh->positions[t[0]], b = mesh->positions[t[1]], c = mesh->positions[t[2]];
    EXPECT_GT((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x), 0.0f);
  }
}

TEST(LoadMesh, BowTieVertexIsSplitLenientlyAndRejectedStrictly) {
  // Two fans (faces 1-2 and 3-5) that share only vertex 1.
  const auto path = writeTestFile("bowtie.obj",
                                  "v 0 0 0\nv 1 0 0\nv 1 1 0\nv -1 0 0\nv -1 -1 0\nv 0 -1 1\nv 0 0 1\n"
                                  "f 1 2 3\nf 1 3 7\nf 1 4 5\nf 1 5 6\nf 1 6 4\n");
  EXPECT_NE(loadError(path, {.strict = true}).find("non-manifold"), std::string::npos);
  LoadReport report;
  auto mesh = loadMesh(path, {}, &report);
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  EXPECT_EQ(report.splitBowTieVertices, 1u);
  EXPECT_EQ(mesh->geometricVertexCount, 8u);  // vertex 1 is now two
  EXPECT_EQ(warningsContaining(report, "bowtie.obj: split 1 bow-tie vertices"), 1u);
  EXPECT_EQ(report.warnings.size(), 1u);
  EXPECT_TRUE(validateMesh(*mesh, "bowtie").ok());
}

TEST(LoadMesh, UnusedVerticesAreDroppedWithAWarningAndRejectedStrictly) {
  const auto path = writeTestFile("unused.off", "OFF\n5 1 0\n0 0 0\n9 9 9\n1 0 0\n0 1 0\n8 8 8\n3 0 2 3\n");
  const auto msg = loadError(path, {.strict = true});
  EXPECT_NE(msg.find("vertex 2 (and 1 more) is used by no face"), std::string::npos) << msg;
  LoadReport report;
  auto mesh = loadMesh(path, {}, &report);
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  EXPECT_EQ(mesh->geometricVertexCount, 3u);
  EXPECT_EQ(report.droppedUnusedVertices, 2u);
  EXPECT_EQ(warningsContaining(report, "unused.off: dropped 2 vertices that no face uses"), 1u);
  EXPECT_EQ(report.warnings.size(), 1u);
}

/// Volume enclosed by the mesh's triangles (divergence theorem), in double.
double signedVolume(const SurfaceMesh& m) {
  double v = 0;
  for (const auto& t : m.triangles) {
    const Float3 a = m.positions[t[0]], b = m.positions[t[1]], c = m.positions[t[2]];
    const double ax = a.x, ay = a.y, az = a.z, bx = b.x, by = b.y, bz = b.z, cx = c.x, cy = c.y, cz = c.z;
    v += (ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx)) / 6.0;
  }
  return v;
}

TEST(LoadMesh, AStandardMeshWithFlippedFacesAndAFinIsRepairedToTheOriginal) {
  // The shared torus with three faces written backwards and one extra face on an edge (a fin).
  const auto torus = std::filesystem::path(TISSUE_TEST_SHARED_DIR) / "meshes" / "torus.obj";
  auto original = loadMesh(torus, {.strict = true});
  ASSERT_TRUE(original.ok()) << original.error().message;
  std::ifstream in(torus);
  std::string text, line;
  int face = 0;
  while (std::getline(in, line)) {
    if (line.rfind("f ", 0) == 0 && (++face == 5 || face == 700 || face == 1234)) {
      std::istringstream corners(line.substr(2));
      std::vector<std::string> c{std::istream_iterator<std::string>(corners), {}};
      line = "f " + c[2] + " " + c[1] + " " + c[0];
    }
    text += line + "\n";
  }
  text += "v 0 9 0\nvt 0 0\nf 41/42 42/43 -1/-1\n";  // on the edge of face 1
  const auto path = writeTestFile("torus_defects.obj", text);
  EXPECT_FALSE(loadMesh(path, {.strict = true}).ok());
  LoadReport report;
  auto repaired = loadMesh(path, {}, &report);
  ASSERT_TRUE(repaired.ok()) << repaired.error().message;
  EXPECT_EQ(report.flippedFaces, 3u);
  EXPECT_EQ(report.splitNonManifoldEdges, 1u);
  EXPECT_EQ(report.warnings.size(), 2u);
  EXPECT_EQ(repaired->triangleCount(), original->triangleCount() + 1);
  EXPECT_TRUE(validateMesh(*repaired, "torus_defects").ok());
  // The torus keeps its orientation: the same enclosed volume (the fin, a flap, adds little).
  repaired->triangles.pop_back();
  EXPECT_NEAR(signedVolume(*repaired), signedVolume(*original), 1e-6 * std::abs(signedVolume(*original)));
}

TEST(LoadMesh, HugeDeclaredCountsFailAtOnceWithOneLine) {
  const auto off =
      loadError(writeTestFile("huge.off", "OFF\n1000000000000 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
  EXPECT_NE(off.find("huge.off: the OFF header declares 1000000000000 vertices"), std::string::npos) << off;
  EXPECT_EQ(off.find('\n'), std::string::npos);
  // A face's corner count is allocated for by OpenMesh's reader (the OFF fuzz target: 2 GiB).
  const auto corners = loadError(
      writeTestFile("corners.off", "OFF\n4 4 6\n0 0 0\n10 0 0\n0 10 0\n0 0 10\n39999999999 0 2012 3\n"));
  EXPECT_NE(corners.find("corners.off:7: a face declares 39999999999 corners, but the mesh has 4 vertices"),
            std::string::npos)
      << corners;
  EXPECT_EQ(corners.find('\n'), std::string::npos);
  // Digits on the keyword line, and counts OpenMesh reads as unsigned on the next ("-01" is
  // 4294967295 faces; the OFF fuzz target found OpenMesh adding faces until the timeout).
  const auto negative = loadError(writeTestFile("negative.off", "OFF 2\n3 -01\n0 0 0\n10 0 0\n0 10 0\n"));
  EXPECT_NE(negative.find("negative.off: the OFF header declares"), std::string::npos) << negative;
  EXPECT_EQ(negative.find('\n'), std::string::npos);
  // Read word by word as OpenMesh does: "10-0" is two words, so the faces start inside the vertex
  // lines and a corner count of "-01" (4294967295) follows (the OFF fuzz target's timeout).
  const auto shifted = loadError(
      writeTestFile("shifted.off", "OFF\n4 4 6\n0 100 0\n10 0 0\n0 10-0\n0 00\n0 010 0 0\n0 0-01 3 1\n"));
  EXPECT_NE(shifted.find("shifted.off: OFF face"), std::string::npos) << shifted;
  EXPECT_NE(shifted.find("corners, but the mesh has 4 vertices (read word by word"), std::string::npos)
      << shifted;
  const auto noCounts = loadError(writeTestFile("no_counts.off", "OFF\n"));
  EXPECT_NE(noCounts.find("no_counts.off: no vertex and face counts after the OFF line"), std::string::npos)
      << noCounts;
  // Binary OFF: a face's corner count is a raw uint32 that OpenMesh loops over (a fuzz timeout).
  std::string binary = "OFF BINARY\n";
  for (const std::uint32_t word : {3u, 1u, 0u})
    binary.append(reinterpret_cast<const char*>(&word), 4);
  binary.append(36, '\0');
  const std::uint32_t corners4g = 4000000000u;
  binary.append(reinterpret_cast<const char*>(&corners4g), 4);
  const auto binaryError = loadError(writeTestFile("corners_binary.off", binary));
  EXPECT_NE(binaryError.find("corners_binary.off: binary OFF face 1 of 1 declares 4000000000 corners"),
            std::string::npos)
      << binaryError;
  std::string stl(84 + 50, '\0');
  const std::uint32_t n = 4000000000u;
  std::memcpy(stl.data() + 80, &n, 4);
  const auto msg = loadError(writeTestFile("huge.stl", stl));
  EXPECT_NE(msg.find("declares 4000000000 triangles, but the file has room for 1"), std::string::npos) << msg;
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
  EXPECT_NE(msg.find("face 2 (line 17) refers to vertex 10"), std::string::npos) << msg;
}

// A 2 x 3 grid of points in the z = 0 plane as one strip (MeshLab's `element tristrips`), with a
// -1 restart and a repeated index joining two strips: every triangle faces +z.
std::string stripPly(const std::string& format) {
  return "ply\nformat " + format +
         " 1.0\ncomment strips as MeshLab writes them\nelement vertex 6\nproperty float x\nproperty float y\n"
         "property float z\nelement tristrips 1\nproperty list int int vertex_indices\nend_header\n";
}
const float kGrid[6][3] = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}, {2, 0, 0}, {2, 1, 0}};
// Strip 0 2 1 3 gives (0,2,1), (2,3,1); after the restart, 2 4 3 3 5 gives (2,4,3) and two
// triangles repeating 3 (a join, no area), skipped. A second list 4 5 3 adds (4,5,3).
const int kStrips[] = {0, 2, 1, 3, -1, 2, 4, 3, 3, 5};

float normalZ(const SurfaceMesh& m, const Triangle& t) {
  const Float3 a = m.positions[t[0]], b = m.positions[t[1]], c = m.positions[t[2]];
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

void expectStripMesh(const std::filesystem::path& path) {
  LoadReport report;
  auto mesh = loadMesh(path, {.strict = true}, &report);
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  EXPECT_EQ(mesh->triangleCount(), 4u);
  EXPECT_EQ(mesh->geometricVertexCount, 6u);
  for (const auto& t : mesh->triangles)
    EXPECT_GT(normalZ(*mesh, t), 0.0f) << "the strip starts counter-clockwise seen from +z (0, 2, 1)";
}

TEST(LoadMesh, PlyTriangleStripsAsciiAndBinary) {
  std::string ascii = stripPly("ascii");
  for (const auto& p : kGrid)
    ascii += std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + "\n";
  ascii += "10 0 2 1 3 -1 2 4 3 3 5\n";
  ascii.replace(ascii.find("element tristrips 1"), 19, "element tristrips 2");
  ascii += "3 4 5 3\n";
  expectStripMesh(writeTestFile("strip.ply", ascii));
  // Some writers declare the strip list unsigned and write the restart as 2^32 - 1.
  std::string unsignedList = ascii;
  unsignedList.replace(unsignedList.find("list int int"), 12, "list int uint");
  unsignedList.replace(unsignedList.find(" -1 "), 4, " 4294967295 ");
  expectStripMesh(writeTestFile("strip_uint.ply", unsignedList));
  for (const bool little : {true, false}) {
    std::string bin = stripPly(little ? "binary_little_endian" : "binary_big_endian");
    bin.replace(bin.find("element tristrips 1"), 19, "element tristrips 2");
    const auto put = [&](const void* v) {
      char b[4];
      std::memcpy(b, v, 4);
      if (!little) std::swap(b[0], b[3]), std::swap(b[1], b[2]);
      bin.append(b, 4);
    };
    for (const auto& p : kGrid)
      for (float c : p)
        put(&c);
    for (const std::vector<int>& strip :
         {std::vector<int>(std::begin(kStrips), std::end(kStrips)), std::vector<int>{4, 5, 3}}) {
      const int n = int(strip.size());
      put(&n);
      for (int idx : strip)
        put(&idx);
    }
    expectStripMesh(writeTestFile(little ? "strip_le.ply" : "strip_be.ply", bin));
  }
}

TEST(LoadMesh, PlyWithExtraListPropertiesReadsTheSameGeometry) {
  const std::string plain = kQuadPly;
  const std::string extra =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty list uchar float weights\n"
      "property float y\nproperty float z\nproperty float u\nproperty float v\nproperty uchar red\n"
      "element face 2\nproperty list uchar int vertex_indices\nproperty list uchar float texcoord\n"
      "property int flags\nelement edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n"
      "0 2 0.5 0.5 0 0 0 0 255\n1 0 0 0 1 0 7\n1 3 1 2 3 1 0 1 1 9\n0 1 9 1 0 0 1 1\n"
      "3 0 1 2 6 0 0 1 0 1 1 5\n3 0 2 3 6 0 0 1 1 0 1 6\n0 1\n";
  auto a = loadMesh(writeTestFile("plain.ply", plain));
  auto b = loadMesh(writeTestFile("extra.ply", extra));
  ASSERT_TRUE(a.ok()) << a.error().message;
  ASSERT_TRUE(b.ok()) << b.error().message;
  EXPECT_EQ(a->triangles, b->triangles);
  EXPECT_EQ(a->positions, b->positions);
  EXPECT_EQ(a->uvs, b->uvs);  // per-corner texcoords equal to the per-vertex u, v
}

TEST(LoadMesh, PlyHugeDeclaredCountFailsAtOnce) {
  std::string ply = kQuadPly;
  ply.replace(ply.find("element vertex 4"), 16, "element vertex 1000000000000");
  const auto msg = loadError(writeTestFile("huge.ply", ply));
  EXPECT_NE(msg.find("huge.ply:3: element 'vertex' declares 1000000000000 entries"), std::string::npos)
      << msg;
  EXPECT_EQ(msg.find('\n'), std::string::npos);
}

TEST(LoadMesh, PlyListLengthBeyondAnyIntegerFailsInOneLine) {
  // A text list length too large for any integer (the PLY fuzzer's UBSan finding: 1e126 was
  // converted to an unsigned count before the size check).
  for (const char* length : {"1e126", "18446744073709551616", "9223372036854775808"}) {
    std::string ply = kQuadPly;
    ply.replace(ply.rfind("3 0 2 3"), 1, length);
    const auto msg = loadError(writeTestFile("long_list.ply", ply));
    EXPECT_NE(msg.find("long_list.ply:"), std::string::npos) << msg;
    EXPECT_NE(msg.find("list 'vertex_indices' declares"), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  }
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
