#pragma once
// Writing small volume files for the reader tests, into the test output folder.

#include <filesystem>
#include <fstream>
#include <string>

namespace tissue::volume::test {

/// Writes `text` to TISSUE_TEST_OUTPUT_DIR/volume/<name> and returns the path.
inline std::filesystem::path writeTestFile(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::path(TISSUE_TEST_OUTPUT_DIR) / "volume";
  std::filesystem::create_directories(dir);
  const auto path = dir / name;
  std::ofstream(path) << text;
  return path;
}

/// Two tets sharing the face (1,2,3) (unit right-angled corner tets, volume 1/6 mm^3 each).
inline const char* kTwoTetPoints = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n";

}  // namespace tissue::volume::test
