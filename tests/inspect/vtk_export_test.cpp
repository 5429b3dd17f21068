#include "tissue/inspect/vtk_export.h"

#include <gtest/gtest.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

namespace tissue::inspect {
namespace {

TEST(VtkExport, RoundTripsPointsTrianglesAndFields) {
  const std::vector<Float3> p = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {10, 10, 2}};
  const std::vector<Triangle> t = {{0, 1, 2}, {1, 3, 2}};
  const std::vector<Float3> n = {{0, 0, 1}, {0, 0.1f, 1}, {0, 0, 1}, {0.2f, 0, 1}};
  const std::vector<float> offset = {0.0f, -0.5f, 0.25f, 1.0f};
  const auto path = std::filesystem::path(TISSUE_TEST_OUTPUT_DIR) / "inspect" / "quad.vtp";
  auto ok = writeVtp(path, p, t, {fieldOf<Float3>("normal", n), {"offset_mm", 1, offset}});
  ASSERT_TRUE(ok.ok()) << ok.error().message;
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  auto* poly = reader->GetOutput();
  ASSERT_EQ(poly->GetNumberOfPoints(), 4);
  ASSERT_EQ(poly->GetNumberOfPolys(), 2);
  double q[3];
  poly->GetPoint(3, q);
  EXPECT_DOUBLE_EQ(q[2], 2.0);
  auto* normal = vtkFloatArray::SafeDownCast(poly->GetPointData()->GetArray("normal"));
  auto* off = vtkFloatArray::SafeDownCast(poly->GetPointData()->GetArray("offset_mm"));
  ASSERT_TRUE(normal && off);
  EXPECT_EQ(normal->GetNumberOfComponents(), 3);
  EXPECT_FLOAT_EQ(normal->GetComponent(1, 1), 0.1f);
  EXPECT_FLOAT_EQ(off->GetValue(1), -0.5f);
}

TEST(VtkExport, RejectsAFieldOfTheWrongSize) {
  const std::vector<Float3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<float> bad = {1.0f, 2.0f};
  const std::vector<Triangle> t = {{0, 1, 2}};
  auto r = writeVtp(std::filesystem::path(TISSUE_TEST_OUTPUT_DIR) / "inspect" / "bad.vtp", p, t,
                    {{"bad", 1, bad}});
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("'bad'"), std::string::npos);
}

}  // namespace
}  // namespace tissue::inspect
