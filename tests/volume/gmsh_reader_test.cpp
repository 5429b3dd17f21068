// The Gmsh reader on every version it reads (v1; v2 with header "2" and "2.2"; v4.1; v2 and v4.1
// binary in both byte orders): the same two tets, a triangle ignored.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

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

TEST(GmshReader, Version2WithoutMinor) {
  // Older writers (and some converters) put "2" alone on the version line.
  expectTwoTets(writeTestFile("v2nominor.msh",
                              "$MeshFormat\n2 0 8\n$EndMeshFormat\n"
                              "$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n$EndNodes\n"
                              "$Elements\n3\n1 2 2 0 1 1 2 3\n2 4 2 0 1 1 2 3 4\n3 4 2 0 1 2 4 3 5\n"
                              "$EndElements\n"));
}

/// Binary .msh content: values appended in the file's byte order (`swap`: the other one).
class Binary {
 public:
  explicit Binary(bool swap) : m_swap(swap) {}
  template <class T>
  Binary& put(T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    if (m_swap) std::reverse(b, b + sizeof(T));
    m_text.append(b, sizeof(T));
    return *this;
  }
  Binary& text(const std::string& t) {
    m_text += t;
    return *this;
  }
  const std::string& str() const { return m_text; }

 private:
  bool m_swap;
  std::string m_text;
};

const double kPoints[5][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};

std::string binaryV2(bool swap) {
  Binary b(swap);
  b.text("$MeshFormat\n2.2 1 8\n").put(std::int32_t{1}).text("\n$EndMeshFormat\n$Nodes\n5\n");
  for (int n = 0; n < 5; ++n)
    b.put(std::int32_t(n + 1)).put(kPoints[n][0]).put(kPoints[n][1]).put(kPoints[n][2]);
  b.text("\n$EndNodes\n$Elements\n3\n");
  // One block of a triangle (type 2, 2 tags), one block of two tets (type 4, 2 tags).
  b.put(std::int32_t{2}).put(std::int32_t{1}).put(std::int32_t{2});
  for (std::int32_t v : {1, 0, 1, 1, 2, 3})
    b.put(v);
  b.put(std::int32_t{4}).put(std::int32_t{2}).put(std::int32_t{2});
  for (std::int32_t v : {2, 0, 1, 1, 2, 3, 4, 3, 0, 1, 2, 4, 3, 5})
    b.put(v);
  b.text("\n$EndElements\n");
  return b.str();
}

std::string binaryV41(bool swap) {
  Binary b(swap);
  b.text("$MeshFormat\n4.1 1 8\n").put(std::int32_t{1}).text("\n$EndMeshFormat\n");
  // A binary $Entities section (one volume) that the reader must skip whole.
  b.text("$Entities\n");
  for (std::uint64_t v : {0, 0, 0, 1})
    b.put(v);
  b.put(std::int32_t{1});
  for (double v : {0.0, 0.0, 0.0, 1.0, 1.0, 1.0})
    b.put(v);
  b.put(std::uint64_t{0}).put(std::uint64_t{0}).text("\n$EndEntities\n$Nodes\n");
  for (std::uint64_t v : {1, 5, 10, 50})
    b.put(v);
  b.put(std::int32_t{3}).put(std::int32_t{1}).put(std::int32_t{0}).put(std::uint64_t{5});
  for (std::uint64_t tag : {10, 20, 30, 40, 50})
    b.put(tag);
  for (const auto& p : kPoints)
    b.put(p[0]).put(p[1]).put(p[2]);
  b.text("\n$EndNodes\n$Elements\n");
  for (std::uint64_t v : {2, 3, 1, 3})
    b.put(v);
  b.put(std::int32_t{2}).put(std::int32_t{1}).put(std::int32_t{2}).put(std::uint64_t{1});
  for (std::uint64_t v : {1, 10, 20, 30})
    b.put(v);
  b.put(std::int32_t{3}).put(std::int32_t{1}).put(std::int32_t{4}).put(std::uint64_t{2});
  for (std::uint64_t v : {2, 10, 20, 30, 40, 3, 20, 40, 30, 50})
    b.put(v);
  b.text("\n$EndElements\n");
  return b.str();
}

TEST(GmshReader, Version2BinaryInBothByteOrders) {
  expectTwoTets(writeTestFile("v2bin.msh", binaryV2(false)));
  expectTwoTets(writeTestFile("v2bin_swapped.msh", binaryV2(true)));
}

TEST(GmshReader, Version41BinaryInBothByteOrders) {
  expectTwoTets(writeTestFile("v41bin.msh", binaryV41(false)));
  expectTwoTets(writeTestFile("v41bin_swapped.msh", binaryV41(true)));
}

TEST(GmshReader, BinaryWithABadCheckIntIsOneLine) {
  std::string bad = binaryV2(false);
  bad[bad.find("\n", bad.find("2.2 1 8")) + 1] = 7;  // the check int is now 7
  auto mesh = loadTetMesh(writeTestFile("badcheck.msh", bad));
  ASSERT_FALSE(mesh.ok());
  EXPECT_NE(mesh.error().message.find("badcheck.msh:2: binary $MeshFormat's check int is 7"),
            std::string::npos)
      << mesh.error().message;
}

TEST(GmshReader, HugeDeclaredCountsFailAtOnceWithOneLine) {
  for (const auto& [name, text] :
       {std::pair<std::string, std::string>{"huge2.msh",
                                            "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
                                            "$Nodes\n1000000000000\n1 0 0 0\n$EndNodes\n"},
        {"huge41.msh",
         "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 1000000000000 1 1000000000000\n"
         "3 1 0 1000000000000\n1\n0 0 0\n$EndNodes\n"},
        {"huge2bin.msh",
         binaryV2(false).replace(binaryV2(false).find("$Nodes\n5\n"), 9, "$Nodes\n999999999\n")}}) {
    auto mesh = loadTetMesh(writeTestFile(name, text));
    ASSERT_FALSE(mesh.ok()) << name;
    const auto& msg = mesh.error().message;
    EXPECT_NE(msg.find(name + ":"), std::string::npos) << msg;
    EXPECT_NE(msg.find("bytes left can hold"), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  }
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
