// tissue-sim kernel-report: Freude 2014's comparisons (Tables 6.3 and 6.5, image-space errors)
// for Apple, Marble, Ketchup, Skin1 and Wholemilk, as Markdown tables, JSON and charts.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <iostream>
#include <map>
#include <sstream>

#include "command.h"
#include "named_material.h"
#include "output.h"
#include "tissue/core/atomic_file.h"
#include "tissue/core/stopwatch.h"
#include "tissue/inspect/chart.h"
#include "tissue/studies/kernel_study.h"

namespace tissue::sim_app {
namespace {

using studies::Rgb;

const char* kMaterials[] = {"Apple", "Marble", "Ketchup", "Skin1", "Wholemilk"};
// Freude's Table 6.3 sums (normalised RGB errors) for SVD1, pre-integration, guided k=1, manual.
const std::map<std::string, std::array<double, 4>> kThesis63 = {{"Apple", {0.181, 0.384, 0.440, 0.330}},
                                                                {"Marble", {0.124, 0.263, 0.299, 0.226}},
                                                                {"Ketchup", {0.379, 0.863, 0.469, 1.833}},
                                                                {"Skin1", {0.192, 0.442, 0.479, 0.557}},
                                                                {"Wholemilk", {0.123, 0.258, 0.296, 0.243}}};
// Freude's Table 6.5 sums (Skin1, Head scene), rank/count 1..6: SVD and d'Eon.
const double kThesis65Svd[] = {1.481, 0.852, 0.432, 0.272, 0.141, 0.088};
const double kThesis65Deon[] = {1.679, 1.406, 0.949, 0.557, 0.330, 0.214};

using studies::KernelStudy;
using studies::rankOneSpecs;
using studies::sum;

std::string fmt(double v, int digits = 3) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

// Table 6.3's form: the four thesis models, each RGB error divided by the largest in the table.
std::string kernelTable(const std::vector<KernelStudy>& studies) {
  const std::vector<std::string> models = {"SVD1",    "Pre-int.", "Guided k=1", "Manual",
                                           "SVD1 N.", "d'Eon 1",  "Jimenez"};
  double top = 0;
  for (const auto& s : studies)
    for (std::size_t m = 0; m < 4; ++m)
      for (double v : s.runs.at(models[m]).kernelRms)
        top = std::max(top, v);
  std::ostringstream t;
  t << "| material |";
  for (const auto& m : models)
    t << " " << m << " R G B (sum) |";
  t << "\n|---|";
  for (std::size_t i = 0; i < models.size(); ++i)
    t << "---|";
  t << "\n";
  for (const auto& s : studies) {
    t << "| " << s.name << " |";
    for (std::size_t m = 0; m < models.size(); ++m) {
      const Rgb& v = s.runs.at(models[m]).kernelRms;
      t << " " << fmt(v[0] / top) << " " << fmt(v[1] / top) << " " << fmt(v[2] / top) << " (**"
        << fmt(sum(v) / top) << "**";
      if (m < 4) t << "; thesis " << fmt(kThesis63.at(s.name)[m]);
      t << ") |";
    }
    t << "\n";
  }
  t << "\nLargest RGB kernel-space RMS in the table (= 1): " << top << " (grid cells sum to 1).\n";
  return t.str();
}

std::string imageTable(const std::vector<KernelStudy>& studies) {
  const auto specs = rankOneSpecs();
  std::ostringstream t;
  t << "| material | signal |";
  for (const auto& s : specs)
    t << " " << s.label << " |";
  t << "\n|---|---|";
  for (std::size_t i = 0; i < specs.size(); ++i)
    t << "---|";
  t << "\n";
  for (const auto& s : studies) {
    for (const auto& [signal, unused] : tissue::studies::kernelStudySignals()) {
      t << "| " << s.name << " | " << signal << " |";
      for (const auto& spec : specs)
        t << " " << fmt(1e3 * sum(s.runs.at(spec.label).imageRms.at(signal)), 2) << " |";
      t << "\n";
    }
  }
  t << "\nSum over RGB of the image-space RMS, x 1e-3 (signals in [0, 1], 256^2 pixels, 17 taps).\n";
  return t.str();
}

// Table 6.5's form for Skin1 (normalised to the largest RGB error of the table), then the sums of
// every material.
std::string rankTable(const std::vector<KernelStudy>& studies, const std::string& signal) {
  std::ostringstream t;
  const auto& skin =
      *std::find_if(studies.begin(), studies.end(), [](const auto& s) { return s.name == "Skin1"; });
  double top = 0;
  for (int k = 1; k <= 6; ++k)
    for (const char* m : {"SVD ", "d'Eon "})
      for (double v : skin.runs.at(m + std::to_string(k)).imageRms.at(signal))
        top = std::max(top, v);
  t << "| k | SVD rank-k R G B (sum) | thesis | d'Eon k R G B (sum) | thesis |";
  for (const auto& s : studies)
    if (s.name != "Skin1") t << " " << s.name << " SVD / d'Eon (x1e-3) |";
  t << "\n|---|---|---|---|---|---|---|---|---|\n";
  for (int k = 1; k <= 6; ++k) {
    const auto& svd = skin.runs.at("SVD " + std::to_string(k)).imageRms.at(signal);
    const auto& deon = skin.runs.at("d'Eon " + std::to_string(k)).imageRms.at(signal);
    t << "| " << k << " | " << fmt(svd[0] / top) << " " << fmt(svd[1] / top) << " " << fmt(svd[2] / top)
      << " (**" << fmt(sum(svd) / top) << "**) | " << fmt(kThesis65Svd[k - 1]) << " | " << fmt(deon[0] / top)
      << " " << fmt(deon[1] / top) << " " << fmt(deon[2] / top) << " (**" << fmt(sum(deon) / top) << "**) | "
      << fmt(kThesis65Deon[k - 1]) << " |";
    for (const auto& s : studies)
      if (s.name != "Skin1")
        t << " " << fmt(1e3 * sum(s.runs.at("SVD " + std::to_string(k)).imageRms.at(signal)), 2) << " / "
          << fmt(1e3 * sum(s.runs.at("d'Eon " + std::to_string(k)).imageRms.at(signal)), 2) << " |";
    t << "\n";
  }
  t << "\nSignal: " << signal << "; Skin1 columns normalised to its largest RGB error (" << top << ").\n";
  return t.str();
}

// The models themselves, before tap sampling: kernel-space RMS (sum over RGB) of SVD rank-k and
// d'Eon k Gaussians, relative to SVD1 of the same material.
std::string rankKernelTable(const std::vector<KernelStudy>& studies) {
  std::ostringstream t;
  t << "| k |";
  for (const auto& s : studies)
    t << " " << s.name << " SVD / d'Eon |";
  t << "\n|---|";
  for (std::size_t i = 0; i < studies.size(); ++i)
    t << "---|";
  t << "\n";
  for (int k = 1; k <= 6; ++k) {
    t << "| " << k << " |";
    for (const auto& s : studies) {
      const double base = sum(s.runs.at("SVD1").kernelRms);
      t << " " << fmt(sum(s.runs.at("SVD " + std::to_string(k)).kernelRms) / base) << " / "
        << fmt(sum(s.runs.at("d'Eon " + std::to_string(k)).kernelRms) / base) << " |";
    }
    t << "\n";
  }
  t << "\nKernel-space RMS (sum over RGB, dense components on the 201^2 grid) relative to SVD rank-1.\n";
  return t.str();
}

std::string timeTable(const std::vector<KernelStudy>& studies) {
  const std::vector<std::string> labels = {"SVD1",    "Pre-int.", "Guided k=1", "Manual",
                                           "d'Eon 1", "d'Eon 6",  "SVD 6",      "Jimenez"};
  std::ostringstream t;
  t << "| material |";
  for (const auto& l : labels)
    t << " " << l << " |";
  t << "\n|---|";
  for (std::size_t i = 0; i < labels.size(); ++i)
    t << "---|";
  t << "\n";
  for (const auto& s : studies) {
    t << "| " << s.name << " |";
    for (const auto& l : labels)
      t << " " << fmt(s.runs.at(l).buildMs, 1) << " (" << fmt(s.runs.at(l).buildCpuMs, 1) << ") |";
    t << "\n";
  }
  t << "\nms per kernel (17 taps), wall (CPU), from the radial profile: 201^2 grid, model, taps; one run "
       "each.\n";
  return t.str();
}

nlohmann::json studyJson(const KernelStudy& s) {
  nlohmann::json j;
  j["grid_cell_mm"] = s.cellMm;
  for (const auto& [label, run] : s.runs) {
    nlohmann::json r;
    r["build_ms"] = run.buildMs;
    r["build_cpu_ms"] = run.buildCpuMs;
    r["kernel_rms"] = run.kernelRms;
    for (const auto& [signal, rms] : run.imageRms)
      r["image_rms"][signal] = rms;
    j["models"][label] = r;
  }
  return j;
}

// Charts: SVD rank-k against d'Eon k Gaussians (Skin1), and Skin1's red kernels along the axis.
std::vector<std::string> writeCharts(const std::filesystem::path& dir,
                                     const std::vector<KernelStudy>& studies) {
  std::vector<std::string> warnings;
  const auto& skin =
      *std::find_if(studies.begin(), studies.end(), [](const auto& s) { return s.name == "Skin1"; });
  std::vector<inspect::ChartSeries> rank;
  for (const char* m : {"SVD ", "d'Eon "}) {
    for (const char* signal : {"shaded patch", "circle+squares"}) {
      inspect::ChartSeries series{std::string(m) + "(" + signal + ")", {}, {}, true};
      for (int k = 1; k <= 6; ++k) {
        series.x.push_back(k);
        series.y.push_back(sum(skin.runs.at(m + std::to_string(k)).imageRms.at(signal)));
      }
      rank.push_back(series);
    }
  }
  auto ok = inspect::writeLineChart(dir / "svd_vs_deon_skin1.png",
                                    {"Skin1: SVD rank-k vs d'Eon k Gaussians (2k passes each)", "k",
                                     "image-space RMS, sum over RGB", false, true, 900, 600},
                                    rank);
  if (!ok) warnings.push_back(ok.error().message);
  std::vector<inspect::ChartSeries> slices;
  auto slice = [&](const std::string& label, const std::vector<double>& v) {
    inspect::ChartSeries series{label, {}, {}, true};
    for (std::size_t x = 0; x < v.size(); ++x) {
      const double mm = (static_cast<double>(x) - skin.halfCells) * skin.cellMm;
      if (std::abs(mm) <= 6.0) {
        series.x.push_back(mm);
        series.y.push_back(v[x]);
      }
    }
    slices.push_back(series);
  };
  slice("ground truth", skin.truthSliceRed);
  for (const char* label : {"SVD1", "SVD1 N.", "Pre-int.", "Guided k=1", "Manual", "d'Eon 1"})
    slice(label, skin.runs.at(label).sliceRed);
  ok = inspect::writeLineChart(dir / "kernels_skin1_red.png",
                               {"Skin1 red: kernels along the x axis (cf. Freude Fig. 5.8)", "x (mm)",
                                "kernel weight per grid cell", false, false, 900, 600},
                               slices);
  if (!ok) warnings.push_back(ok.error().message);
  return warnings;
}

int runKernelReport(const std::filesystem::path& dir, const GlobalOptions& global) {
  std::vector<KernelStudy> studies;
  for (const char* name : kMaterials) {
    auto material = findNamedMaterial(name);
    if (!material) return fail("kernel-report", material.error().message);
    auto s = tissue::studies::studyKernels(*material);
    if (!s) return fail("kernel-report", s.error().message);
    studies.push_back(std::move(*s));
  }
  std::ostringstream md;
  md << "# Separable SSS kernels (tissue-sim kernel-report)\n\n"
     << "Ground truth: dipole profiles rotated into 201^2 grids, each channel normalised to 1.\n\n"
     << "## Kernel-space RMS (cf. Freude Table 6.3)\n\n"
     << kernelTable(studies) << "\n## Image-space RMS per model\n\n"
     << imageTable(studies) << "\n## SVD rank-k vs d'Eon k Gaussians (cf. Freude Table 6.5)\n\n"
     << rankTable(studies, "shaded patch") << "\n"
     << rankTable(studies, "circle+squares") << "\n"
     << rankKernelTable(studies) << "\n## Build time per kernel\n\n"
     << timeTable(studies);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return fail("kernel-report", "cannot create " + dir.string() + ": " + ec.message());
  nlohmann::json out;
  for (const auto& s : studies)
    out["materials"][s.name] = studyJson(s);
  if (auto ok = writeTextFileAtomic(dir / "kernel_report.md", md.str()); !ok)
    return fail("kernel-report", ok.error().message);
  if (auto ok = writeTextFileAtomic(dir / "kernel_report.json", out.dump(1)); !ok)
    return fail("kernel-report", ok.error().message);
  const auto warnings = writeCharts(dir, studies);
  for (const auto& w : warnings)
    std::cerr << "tissue-sim kernel-report: warning: chart not written: " << w << "\n";
  out["files"] = {(dir / "kernel_report.md").string(), (dir / "kernel_report.json").string(),
                  (dir / "svd_vs_deon_skin1.png").string(), (dir / "kernels_skin1_red.png").string()};
  if (global.json) {
    printResult(global, out);
  } else {
    std::cout << md.str() << "\nwritten to " << dir.string() << "\n";
  }
  return 0;
}

}  // namespace

void registerKernelReportCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto dir = std::make_shared<std::string>("out/kernel-report");
  auto* cmd =
      app.add_subcommand("kernel-report",
                         "Freude's kernel comparisons for Apple, Marble, Ketchup, Skin1, Wholemilk: tables, "
                         "charts");
  cmd->add_option("--out", *dir, "output folder (default out/kernel-report)");
  cmd->callback([dir, &global, &exitCode] { exitCode = runKernelReport(*dir, global); });
}

}  // namespace tissue::sim_app
