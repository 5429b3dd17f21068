// VTK surfaces (legacy POLYDATA with POLYGONS and TRIANGLE_STRIPS, XML PolyData in a .vtk file)
// load as surface meshes through the mesh loader, as MeshLab and ParaView open them.
#include <gtest/gtest.h>

#include "test_files.h"
#include "tissue/mesh/load_mesh.h"
#include "tissue/volume/tet_mesh.h"
#include "tissue/volume/vtk_surface.h"

namespace tissue::volume {
namespace {

using test::writeTestFile;

float normalZ(const SurfaceMesh& m, const Triangle& t) {
  const Float3 a = m.positions[t[0]], b = m.positions[t[1]], c = m.positions[t[2]];
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// A 2 x 3 grid in z = 0: one quad polygon (0 2 3 1) and one strip (2 4 3 5), all facing +z, and
// a LINES cell that a surface does not keep.
const char* kPolyData =
    "# vtk DataFile Version 3.0\nsurface\nASCII\nDATASET POLYDATA\nPOINTS 6 float\n"
    "0 0 0 0 1 0 1 0 0 1 1 0 2 0 0 2 1 0\nPOLYGONS 1 5\n4 0 2 3 1\nTRIANGLE_STRIPS 1 5\n4 2 4 3 5\n"
    "LINES 1 3\n2 0 1\n";

TEST(VtkSurface, PolyDataLoadsAsASurface) {
  const auto path = writeTestFile("surface.vtk", kPolyData);
  EXPECT_TRUE(isVtkSurfacePath(path));
  EXPECT_FALSE(isTetMeshPath(path));
  mesh::LoadReport report;
  auto mesh = mesh::loadMesh(path, {}, &report);
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  EXPECT_EQ(mesh->triangleCount(), 4u);  // the quad's fan (2) and the strip (2)
  EXPECT_EQ(mesh->geometricVertexCount, 6u);
  for (const auto& t : mesh->triangles)
    EXPECT_GT(normalZ(*mesh, t), 0.0f);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_NE(report.warnings[0].find("surface.vtk: ignored 1 VERTICES and LINES cells"), std::string::npos)
      << report.warnings[0];
  // Strict loading takes the same surface (nothing needed repair).
  EXPECT_TRUE(mesh::loadMesh(path, {.strict = true}).ok());
}

TEST(VtkSurface, XmlPolyDataInAVtkFileLoadsAsASurface) {
  const auto path = writeTestFile(
      "xml_surface.vtk",
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\">\n<PolyData>\n"
      "<Piece NumberOfPoints=\"4\" NumberOfPolys=\"2\">\n<Points><DataArray type=\"Float32\" "
      "NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0 0 1 1 0 0 1 0</DataArray></Points>\n"
      "<Polys><DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 1 2 0 2 3</DataArray>\n"
      "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">3 6</DataArray></Polys>\n"
      "</Piece>\n</PolyData>\n</VTKFile>\n");
  EXPECT_TRUE(isVtkSurfacePath(path));
  auto mesh = mesh::loadMesh(path);
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  EXPECT_EQ(mesh->triangleCount(), 2u);
  EXPECT_EQ(mesh->geometricVertexCount, 4u);
}

TEST(VtkSurface, BadSurfaceIsOneLine) {
  const auto path = writeTestFile(
      "short_surface.vtk", "# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 4 float\n0 0 0\n");
  testing::internal::CaptureStderr();
  auto mesh = mesh::loadMesh(path);
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  ASSERT_FALSE(mesh.ok());
  EXPECT_EQ(mesh.error().message.rfind(path.string() + ": VTK could not read it", 0), 0u)
      << mesh.error().message;
  EXPECT_EQ(mesh.error().message.find('\n'), std::string::npos);
}

// VTK 9.1's vtkPolyDataReader crashes on a cell section that ends early or holds a non-number;
// the adapter counts the sections first, so these are one line, not a SIGSEGV.
TEST(VtkSurface, TruncatedOrDamagedCellSectionsAreOneLineNotACrash) {
  const std::string head =
      "# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 4 float\n"
      "0 0 0 1 0 0 0 1 0 1 1 0\nPOLYGONS 1 4\n";
  const auto truncated = mesh::loadMesh(writeTestFile("cut_polygons.vtk", head + "3 0 1 "));
  ASSERT_FALSE(truncated.ok());
  EXPECT_NE(truncated.error().message.find(
                "cut_polygons.vtk:7: POLYGONS declares 4 integers, but entry 4 is past the end of the file"),
            std::string::npos)
      << truncated.error().message;
  const auto damaged = mesh::loadMesh(writeTestFile("bad_polygons.vtk", head + "3\xcb"
                                                                               "0 1 2\n"));
  ASSERT_FALSE(damaged.ok());
  EXPECT_NE(damaged.error().message.find("bad_polygons.vtk:7: POLYGONS declares 4 integers, but entry 1 is"),
            std::string::npos)
      << damaged.error().message;
  EXPECT_EQ(damaged.error().message.find('\n'), std::string::npos);
}

}  // namespace
}  // namespace tissue::volume
