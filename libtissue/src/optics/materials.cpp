// The material library (materials.h): Jensen 2001 and d'Eon TSV tables, data/materials JSON.
#include "tissue/optics/materials.h"

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

namespace tissue::optics {
namespace {

// Rows of a whitespace-separated table, '#' comments and the header row (`headerFirst`) skipped.
// Each row is checked to have `columns` fields; numbers from column 1 (or 0) on are parsed.
struct Row {
  std::string first;
  std::vector<double> numbers;
};

Result<std::vector<Row>> readTable(const std::filesystem::path& path, const std::string& headerFirst,
                                   std::size_t columns, bool firstIsName) {
  std::ifstream in(path);
  if (!in) return Error{"table " + path.string() + ": cannot be read; check the path"};
  std::vector<Row> rows;
  std::string line;
  for (int lineNo = 1; std::getline(in, line); ++lineNo) {
    std::istringstream fields(line);
    std::vector<std::string> f;
    for (std::string s; fields >> s;)
      f.push_back(s);
    if (f.empty() || f[0][0] == '#' || f[0] == headerFirst) continue;
    const std::string where = "table " + path.string() + ", line " + std::to_string(lineNo);
    if (f.size() != columns)
      return Error{where + ": expected " + std::to_string(columns) + " columns, found " +
                   std::to_string(f.size())};
    Row row;
    row.first = f[0];
    for (std::size_t c = firstIsName ? 1 : 0; c < f.size(); ++c) {
      std::size_t used = 0;
      double v = 0;
      try {
        v = std::stod(f[c], &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != f[c].size() || !std::isfinite(v))
        return Error{where + ": column " + std::to_string(c + 1) + " '" + f[c] + "' is not a number"};
      row.numbers.push_back(v);
    }
    rows.push_back(std::move(row));
  }
  if (rows.empty()) return Error{"table " + path.string() + ": holds no rows"};
  return rows;
}

char lower(char c) {
  return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
}

bool equalsIgnoringCase(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (lower(a[i]) != lower(b[i])) return false;
  return true;
}

}  // namespace

Result<std::vector<ScatteringMaterial>> loadJensenMaterials(const std::filesystem::path& tsv) {
  auto rows = readTable(tsv, "material", 8, true);
  if (!rows) return rows.error();
  std::vector<ScatteringMaterial> out;
  for (const auto& row : *rows) {
    ScatteringMaterial m;
    m.name = row.first;
    for (int c = 0; c < kChannels; ++c) {
      m.sigmaS[c] = row.numbers[static_cast<std::size_t>(c)];  // g = 0, so sigma_s = sigma_s'
      m.sigmaA[c] = row.numbers[static_cast<std::size_t>(3 + c)];
    }
    m.g = 0.0;
    m.eta = row.numbers[6];
    m.source = "Jensen et al. 2001, measured coefficients (" + tsv.filename().string() + ")";
    out.push_back(std::move(m));
  }
  return out;
}

Result<ScatteringMaterial> findMaterial(const std::vector<ScatteringMaterial>& materials,
                                        std::string_view name) {
  std::string names;
  for (const auto& m : materials) {
    if (equalsIgnoringCase(m.name, name)) return m;
    names += (names.empty() ? "" : ", ") + m.name;
  }
  return Error{"material '" + std::string(name) + "' is unknown; known: " + names};
}

LayeredMedium halfSpace(const ScatteringMaterial& m, int channel) {
  const auto c = static_cast<std::size_t>(channel);
  LayeredMedium medium;
  medium.ambientAbove = 1.0;
  medium.ambientBelow = 1.0;
  medium.layers.push_back(
      {.n = m.eta, .mua = m.sigmaA[c], .mus = m.sigmaS[c], .g = m.g, .thickness = kInfiniteThickness});
  return medium;
}

Result<GaussianSum> loadDeonGaussians(const std::filesystem::path& tsv) {
  auto rows = readTable(tsv, "variance_mm2", 4, false);
  if (!rows) return rows.error();
  GaussianSum sum;
  for (const auto& row : *rows) {
    sum.varianceMm2.push_back(row.numbers[0]);
    for (std::size_t c = 0; c < kChannels; ++c)
      sum.weights[c].push_back(row.numbers[1 + c]);
  }
  return sum;
}

double gaussianSumProfile(const GaussianSum& sum, int channel, double r) {
  double value = 0;
  const auto& w = sum.weights[static_cast<std::size_t>(channel)];
  for (std::size_t i = 0; i < sum.varianceMm2.size(); ++i) {
    const double v = sum.varianceMm2[i];
    value += w[i] * std::exp(-r * r / (2.0 * v)) / (2.0 * std::numbers::pi * v);
  }
  return value;
}

}  // namespace tissue::optics
