#pragma once
// The project's data organs for the studies tests: data/meshes/<stem>.obj with
// data/materials/<stem>.json, the build's generated textures before the committed ones.

#include <algorithm>
#include <filesystem>
#include <string>

#include "tissue/scene/organ_assets.h"

namespace tissue::studies::testdata {

inline scene::OrganSource dataOrgan(const std::string& stem) {
  const std::filesystem::path data = TISSUE_TEST_DATA_DIR;
  scene::OrganSource source;
  source.mesh = data / "meshes" / (stem + ".obj");
  source.material = data / "materials" / (stem + ".json");
  source.materialOptions.textureRoots = {TISSUE_TEST_GENERATED_DATA_DIR, data};
  return source;
}

/// Lines of `text` (a CSV table: the header and one line per row).
inline std::size_t lineCount(const std::string& text) {
  return std::size_t(std::count(text.begin(), text.end(), '\n'));
}

/// The text of the report file `name`, empty when the report has none.
template <class Report>
std::string fileText(const Report& report, const std::string& name) {
  for (const auto& f : report.files)
    if (f.name == name) return f.text;
  return {};
}

}  // namespace tissue::studies::testdata
