// tissue-sim kernel-report: Freude 2014's comparisons (Tables 6.3 and 6.5, image-space errors)
// for Apple, Marble, Ketchup, Skin1 and Wholemilk, as Markdown tables, JSON and charts
// (tissue/studies/kernel_report.h).
#include <iostream>

#include "command.h"
#include "named_material.h"
#include "output.h"
#include "tissue/studies/kernel_report.h"

namespace tissue::sim_app {
namespace {

int runKernelReport(const std::filesystem::path& dir, const GlobalOptions& global) {
  std::vector<optics::ScatteringMaterial> materials;
  for (const char* name : studies::kKernelReportMaterials) {
    auto material = findNamedMaterial(name);
    if (!material) return fail("kernel-report", material.error().message);
    materials.push_back(*material);
  }
  auto r = studies::kernelReport(materials);
  if (!r) return fail("kernel-report", r.error().message);
  if (int rc = writeReportTo("kernel-report", dir, r->report)) return rc;
  if (!global.json) {
    std::cout << r->markdown << "\nwritten to " << dir.string() << "\n";
    return 0;
  }
  auto out = nlohmann::json::parse(r->json);
  for (const auto& file : r->report.files)
    out["files"].push_back((dir / file.name).string());
  for (const auto& chart : r->report.charts)
    out["files"].push_back((dir / chart.name).string());
  printResult(global, out);
  return 0;
}

}  // namespace

void registerKernelReportCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto dir = std::make_shared<std::string>("out/kernel-report");
  auto* cmd = app.add_subcommand(
      "kernel-report",
      "Freude's kernel comparisons for Apple, Marble, Ketchup, Skin1, Wholemilk: tables, charts");
  cmd->add_option("--out", *dir, "output folder (default out/kernel-report)");
  cmd->callback([dir, &global, &exitCode] { exitCode = runKernelReport(*dir, global); });
}

}  // namespace tissue::sim_app
