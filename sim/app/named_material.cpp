// Material lookup by name for the optics commands (named_material.h).
#include "named_material.h"

#include <cctype>
#include <filesystem>

#include "organ_data.h"
#include "output.h"

namespace tissue::sim_app {
namespace {

std::string lowerCase(std::string s) {
  for (char& c : s)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

Result<optics::ScatteringMaterial> findNamedMaterial(const std::string& name) {
  const auto table = sharedDir() / "reference" / "jensen2001_materials.tsv";
  auto jensen = optics::loadJensenMaterials(table);
  if (!jensen) return jensen.error();
  if (auto m = optics::findMaterial(*jensen, name)) return m;
  std::string known;
  for (const auto& m : *jensen)
    known += m.name + ", ";
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dataDir() / "materials", ec)) {
    if (entry.path().extension() != ".json") continue;
    if (lowerCase(entry.path().stem().string()) == lowerCase(name)) {
      auto file = readDataMaterial(entry.path());
      if (!file) return file.error();
      return scene::opticalMaterial(*file);
    }
    known += entry.path().stem().string() + ", ";
  }
  return Error{"unknown material '" + name + "'; known: " + known.substr(0, known.size() - 2) +
               " (or pass --medium FILE.json)"};
}

}  // namespace tissue::sim_app
