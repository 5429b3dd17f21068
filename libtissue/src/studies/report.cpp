// Study reports (report.h).
#include "tissue/studies/report.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "tissue/core/atomic_file.h"

namespace tissue::studies {
namespace {

std::vector<std::string> padded(const std::vector<std::string>& row, std::size_t n) {
  std::vector<std::string> out = row;
  out.resize(std::max(n, row.size()));
  return out;
}

std::string csvCell(const std::string& cell) {
  if (cell.find_first_of(",\"\n\r") == std::string::npos) return cell;
  std::string quoted = "\"";
  for (char c : cell)
    quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string printed(bool fixedPoint, int digits, double value) {
  if (std::isnan(value)) return "-";
  char buffer[64];
  if (fixedPoint)
    std::snprintf(buffer, sizeof buffer, "%.*f", digits, value);
  else
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  return buffer;
}

}  // namespace

std::string markdownTable(const Table& table) {
  const std::size_t n = table.header.size();
  std::ostringstream out;
  auto line = [&out](const std::vector<std::string>& cells) {
    out << "|";
    for (const auto& cell : cells)
      out << " " << cell << " |";
    out << "\n";
  };
  line(table.header);
  out << "|";
  for (std::size_t i = 0; i < n; ++i)
    out << "---|";
  out << "\n";
  for (const auto& row : table.rows)
    line(padded(row, n));
  return out.str();
}

std::string csvTable(const Table& table) {
  const std::size_t n = table.header.size();
  std::ostringstream out;
  auto line = [&out](const std::vector<std::string>& cells) {
    for (std::size_t i = 0; i < cells.size(); ++i)
      out << (i ? "," : "") << csvCell(cells[i]);
    out << "\n";
  };
  line(table.header);
  for (const auto& row : table.rows)
    line(padded(row, n));
  return out.str();
}

std::string fixed(double value, int digits) {
  return printed(true, digits, value);
}
std::string general(double value, int digits) {
  return printed(false, digits, value);
}

Result<void> writeReport(const std::filesystem::path& dir, const Report& report) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return Error{"cannot create the folder " + dir.string() + ": " + ec.message()};
  for (const auto& file : report.files)
    if (auto ok = writeTextFileAtomic(dir / file.name, file.text); !ok) return ok;
  for (const auto& chart : report.charts)
    if (auto ok = inspect::writeLineChart(dir / chart.name, chart.settings, chart.series); !ok)
      return Error{chart.name + ": " + ok.error().message};
  return {};
}

}  // namespace tissue::studies
