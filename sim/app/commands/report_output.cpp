// Where a command's report goes (report_output.h).
#include "report_output.h"

#include <cstdio>
#include <filesystem>

#include "output.h"

namespace tissue::sim_app {
namespace {

// Gives each entry of `items` its place, as an absolute path (writeReport's folder then does not
// apply), or drops them all when there is none.
template <class T>
void place(std::vector<T>& items, const std::string& folder, const std::string& file,
           const std::string& out) {
  for (T& item : items) {
    if (!file.empty())
      item.name = std::filesystem::absolute(file).string();
    else if (!folder.empty())
      item.name = std::filesystem::absolute(std::filesystem::path(folder) / item.name).string();
  }
  if (file.empty() && folder.empty() && out.empty()) items.clear();
}

}  // namespace

Result<void> writeReportTo(studies::Report report, const ReportPlaces& places) {
  if (places.out.empty()) report.files.clear();
  place(report.images, places.images, places.image, places.out);
  place(report.charts, "", places.chart, places.out);
  if (report.files.empty() && report.images.empty() && report.charts.empty()) return {};
  return studies::writeReport(places.out.empty() ? std::string(".") : places.out, report);
}

int finishStudy(const char* command, studies::StudyOutput output, const ReportPlaces& places,
                const GlobalOptions& global) {
  if (auto w = writeReportTo(std::move(output.report), places); !w) return fail(command, w.error().message);
  if (global.json)
    printResult(global, nlohmann::json::parse(output.json));
  else
    std::fputs(output.summary.c_str(), stdout);
  return 0;
}

}  // namespace tissue::sim_app
