// The springs command's network summary: a closed cube's surface springs are its 18 edges, its
// lattice has mass, and a surface asked for tet edges is refused naming the file.
#include "tissue/studies/spring_network_report.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "tissue/core/atomic_file.h"

namespace tissue::studies {
namespace {

std::filesystem::path cubeObj() {
  const auto file = std::filesystem::temp_directory_path() / "tissue_spring_network_cube.obj";
  EXPECT_TRUE(writeTextFileAtomic(
      file,
      "v 0 0 0\nv 10 0 0\nv 10 10 0\nv 0 10 0\nv 0 0 10\nv 10 0 10\nv 10 10 10\nv 0 10 10\n"
      "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\n"
      "f 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n"));
  return file;
}

TEST(SpringNetworkReport, SourcesRoundTrip) {
  for (auto s : {SpringSource::Surface, SpringSource::TetEdges, SpringSource::Lattice})
    EXPECT_EQ(parseSpringSource(springSourceName(s)), s);
  EXPECT_FALSE(parseSpringSource("springs"));
}

TEST(SpringNetworkReport, CubeSurfaceSpringsAreItsEdgesAndItsLatticeHasMass) {
  SpringNetworkConfig config;
  config.source = SpringSource::Surface;
  config.repeats = 1;
  auto surface = buildSpringNetworkSummary(cubeObj(), config);
  ASSERT_TRUE(surface) << surface.error().message;
  EXPECT_EQ(surface->surfaceVertices, 8u);
  EXPECT_EQ(surface->surfaceTriangles, 12u);
  EXPECT_EQ(surface->springs, 18u);  // Euler: E = V + F - 2, no bending springs asked for
  EXPECT_FALSE(surface->massG);

  config.source = std::nullopt;  // a surface file: the lattice
  config.latticeCells = 4;
  auto lattice = buildSpringNetworkSummary(cubeObj(), config);
  ASSERT_TRUE(lattice) << lattice.error().message;
  EXPECT_EQ(lattice->source, SpringSource::Lattice);
  ASSERT_TRUE(lattice->lattice && lattice->massG);
  EXPECT_GT(*lattice->massG, 0.0);
  EXPECT_EQ(lattice->simVertices, lattice->lattice->nodeCount());
  EXPECT_NEAR(lattice->lattice->filledVolume, 1000.0, 500.0);  // the 10 mm cube, in whole cells
  const std::string json = springNetworkJson(*lattice);
  for (const char* key :
       {"\"grid_cells\"", "\"mass_g\"", "\"source\": \"lattice\"", "\"surface_vertices\": 8"})
    EXPECT_NE(json.find(key), std::string::npos) << key;
}

TEST(SpringNetworkReport, TetEdgesNeedAVolumeMesh) {
  SpringNetworkConfig config;
  config.source = SpringSource::TetEdges;
  auto r = buildSpringNetworkSummary(cubeObj(), config);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("tissue_spring_network_cube.obj"), std::string::npos);
}

}  // namespace
}  // namespace tissue::studies
