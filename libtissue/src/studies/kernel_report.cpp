// Freude 2014's kernel comparisons as a report (kernel_report.h).
#include "tissue/studies/kernel_report.h"

#include <algorithm>
#include <cmath>

#include "json_text.h"

namespace tissue::studies {
namespace {

const std::vector<std::string> kTable63Columns = {"SVD1",    "Pre-int.", "Guided k=1", "Manual",
                                                  "SVD1 N.", "d'Eon 1",  "Jimenez"};

const KernelStudy& skin1(const std::vector<KernelStudy>& studies) {
  return *std::find_if(studies.begin(), studies.end(), [](const auto& s) { return s.name == "Skin1"; });
}

std::string rank(const char* model, int k) {
  return model + std::to_string(k);
}

/// "R G B (**sum**" with every channel divided by `scale`.
std::string rgbCell(const Rgb& v, double scale) {
  return fixed(v[0] / scale) + " " + fixed(v[1] / scale) + " " + fixed(v[2] / scale) + " (**" +
         fixed(sum(v) / scale) + "**";
}

std::vector<std::string> header(std::string first, const std::vector<std::string>& columns,
                                const char* suffix) {
  std::vector<std::string> h{std::move(first)};
  for (const auto& c : columns)
    h.push_back(c + suffix);
  return h;
}

Table imageTable(const std::vector<KernelStudy>& studies) {
  std::vector<std::string> labels;
  for (const auto& spec : rankOneSpecs())
    labels.push_back(spec.label);
  Table t{header("material", labels, ""), {}};
  t.header.insert(t.header.begin() + 1, "signal");
  for (const auto& s : studies)
    for (const auto& [signal, unused] : kernelStudySignals()) {
      std::vector<std::string> row{s.name, signal};
      for (const auto& l : labels)
        row.push_back(fixed(1e3 * sum(s.runs.at(l).imageRms.at(signal)), 2));
      t.rows.push_back(row);
    }
  return t;
}

// The models themselves, before tap sampling: kernel-space RMS (sum over RGB) of SVD rank-k and
// d'Eon k Gaussians, relative to SVD1 of the same material.
Table rankKernelTable(const std::vector<KernelStudy>& studies) {
  Table t{{"k"}, {}};
  for (const auto& s : studies)
    t.header.push_back(s.name + " SVD / d'Eon");
  for (int k = 1; k <= 6; ++k) {
    std::vector<std::string> row{std::to_string(k)};
    for (const auto& s : studies) {
      const double base = sum(s.runs.at("SVD1").kernelRms);
      row.push_back(fixed(sum(s.runs.at(rank("SVD ", k)).kernelRms) / base) + " / " +
                    fixed(sum(s.runs.at(rank("d'Eon ", k)).kernelRms) / base));
    }
    t.rows.push_back(row);
  }
  return t;
}

Table timeTable(const std::vector<KernelStudy>& studies) {
  const std::vector<std::string> labels = {"SVD1",    "Pre-int.", "Guided k=1", "Manual",
                                           "d'Eon 1", "d'Eon 6",  "SVD 6",      "Jimenez"};
  Table t{header("material", labels, ""), {}};
  for (const auto& s : studies) {
    std::vector<std::string> row{s.name};
    for (const auto& l : labels)
      row.push_back(fixed(s.runs.at(l).buildMs, 1) + " (" + fixed(s.runs.at(l).buildCpuMs, 1) + ")");
    t.rows.push_back(row);
  }
  return t;
}

nlohmann::json studyJson(const KernelStudy& s) {
  nlohmann::json j;
  j["grid_cell_mm"] = s.cellMm;
  for (const auto& [label, run] : s.runs) {
    nlohmann::json r{
        {"build_ms", run.buildMs}, {"build_cpu_ms", run.buildCpuMs}, {"kernel_rms", run.kernelRms}};
    for (const auto& [signal, rms] : run.imageRms)
      r["image_rms"][signal] = rms;
    j["models"][label] = r;
  }
  return j;
}

// Charts: SVD rank-k against d'Eon k Gaussians (Skin1), and Skin1's red kernels along the axis.
void addCharts(const std::vector<KernelStudy>& studies, Report& report) {
  const auto& skin = skin1(studies);
  std::vector<inspect::ChartSeries> ranks;
  for (const char* m : {"SVD ", "d'Eon "})
    for (const char* signal : {"shaded patch", "circle+squares"}) {
      inspect::ChartSeries series{std::string(m) + "(" + signal + ")", {}, {}, true};
      for (int k = 1; k <= 6; ++k) {
        series.x.push_back(k);
        series.y.push_back(sum(skin.runs.at(rank(m, k)).imageRms.at(signal)));
      }
      ranks.push_back(series);
    }
  inspect::ChartSettings chart;  // named, not a temporary: GCC 12 warns of a maybe-uninitialized copy
  chart.title = "Skin1: SVD rank-k vs d'Eon k Gaussians (2k passes each)";
  chart.xLabel = "k";
  chart.yLabel = "image-space RMS, sum over RGB";
  chart.logY = true;
  report.charts.push_back({"svd_vs_deon_skin1.png", chart, ranks});
  std::vector<inspect::ChartSeries> slices;
  auto slice = [&](const std::string& label, const std::vector<double>& v) {
    inspect::ChartSeries series{label, {}, {}, true};
    for (std::size_t x = 0; x < v.size(); ++x) {
      const double mm = (static_cast<double>(x) - skin.halfCells) * skin.cellMm;
      if (std::abs(mm) <= 6.0) series.x.push_back(mm), series.y.push_back(v[x]);
    }
    slices.push_back(series);
  };
  slice("ground truth", skin.truthSliceRed);
  for (const char* label : {"SVD1", "SVD1 N.", "Pre-int.", "Guided k=1", "Manual", "d'Eon 1"})
    slice(label, skin.runs.at(label).sliceRed);
  chart.title = "Skin1 red: kernels along the x axis (cf. Freude Fig. 5.8)";
  chart.xLabel = "x (mm)";
  chart.yLabel = "kernel weight per grid cell";
  chart.logY = false;
  report.charts.push_back({"kernels_skin1_red.png", chart, slices});
}

}  // namespace

double kernelSpaceScale(const std::vector<KernelStudy>& studies) {
  double top = 0;
  for (const auto& s : studies)
    for (const char* m : kFreude2014Table63Models)
      for (double v : s.runs.at(m).kernelRms)
        top = std::max(top, v);
  return top;
}

Table kernelSpaceTable(const std::vector<KernelStudy>& studies, double scale) {
  Table t{header("material", kTable63Columns, " R G B (sum)"), {}};
  for (const auto& s : studies) {
    const auto thesis = std::find_if(kFreude2014Table63.begin(), kFreude2014Table63.end(),
                                     [&](const auto& row) { return s.name == row.material; });
    std::vector<std::string> row{s.name};
    for (std::size_t m = 0; m < kTable63Columns.size(); ++m) {
      std::string cell = rgbCell(s.runs.at(kTable63Columns[m]).kernelRms, scale);
      if (m < 4 && thesis != kFreude2014Table63.end()) cell += "; thesis " + fixed(thesis->sums[m]);
      row.push_back(cell + ")");
    }
    t.rows.push_back(row);
  }
  return t;
}

double rankScale(const std::vector<KernelStudy>& studies, const std::string& signal) {
  const auto& skin = skin1(studies);
  double top = 0;
  for (int k = 1; k <= 6; ++k)
    for (const char* m : {"SVD ", "d'Eon "})
      for (double v : skin.runs.at(rank(m, k)).imageRms.at(signal))
        top = std::max(top, v);
  return top;
}

Table rankTable(const std::vector<KernelStudy>& studies, const std::string& signal, double scale) {
  const auto& skin = skin1(studies);
  Table t{{"k", "SVD rank-k R G B (sum)", "thesis", "d'Eon k R G B (sum)", "thesis"}, {}};
  for (const auto& s : studies)
    if (s.name != "Skin1") t.header.push_back(s.name + " SVD / d'Eon (x1e-3)");
  for (int k = 1; k <= 6; ++k) {
    const auto i = static_cast<std::size_t>(k - 1);
    std::vector<std::string> row{std::to_string(k),
                                 rgbCell(skin.runs.at(rank("SVD ", k)).imageRms.at(signal), scale) + ")",
                                 fixed(kFreude2014Table65Svd[i]),
                                 rgbCell(skin.runs.at(rank("d'Eon ", k)).imageRms.at(signal), scale) + ")",
                                 fixed(kFreude2014Table65Deon[i])};
    for (const auto& s : studies)
      if (s.name != "Skin1")
        row.push_back(fixed(1e3 * sum(s.runs.at(rank("SVD ", k)).imageRms.at(signal)), 2) + " / " +
                      fixed(1e3 * sum(s.runs.at(rank("d'Eon ", k)).imageRms.at(signal)), 2));
    t.rows.push_back(row);
  }
  return t;
}

Result<KernelReport> kernelReport(const std::vector<optics::ScatteringMaterial>& materials) {
  KernelReport r;
  for (const auto& material : materials) {
    auto s = studyKernels(material);
    if (!s) return s.error();
    r.studies.push_back(std::move(*s));
  }
  if (std::none_of(r.studies.begin(), r.studies.end(), [](const auto& s) { return s.name == "Skin1"; }))
    return Error{"the kernel report needs Skin1 among its materials (Freude 2014, Table 6.5)"};
  const double top = kernelSpaceScale(r.studies);
  std::string md =
      "# Separable SSS kernels (tissue-sim kernel-report)\n\n"
      "Ground truth: dipole profiles rotated into 201^2 grids, each channel normalised to 1.\n\n"
      "## Kernel-space RMS (cf. Freude Table 6.3)\n\n" +
      markdownTable(kernelSpaceTable(r.studies, top)) +
      "\nLargest RGB kernel-space RMS in the table (= 1): " + general(top) +
      " (grid cells sum to 1).\n\n## Image-space RMS per model\n\n" + markdownTable(imageTable(r.studies)) +
      "\nSum over RGB of the image-space RMS, x 1e-3 (signals in [0, 1], 256^2 pixels, 17 taps).\n"
      "\n## SVD rank-k vs d'Eon k Gaussians (cf. Freude Table 6.5)\n\n";
  for (const char* signal : {"shaded patch", "circle+squares"}) {
    const double scale = rankScale(r.studies, signal);
    md += markdownTable(rankTable(r.studies, signal, scale)) + "\nSignal: " + signal +
          "; Skin1 columns normalised to its largest RGB error (" + general(scale) + ").\n\n";
  }
  md += markdownTable(rankKernelTable(r.studies)) +
        "\nKernel-space RMS (sum over RGB, dense components on the 201^2 grid) relative to SVD rank-1.\n"
        "\n## Build time per kernel\n\n" +
        markdownTable(timeTable(r.studies)) +
        "\nms per kernel (17 taps), wall (CPU), from the radial profile: 201^2 grid, model, taps; one run "
        "each.\n";
  r.markdown = md;
  nlohmann::json out;
  for (const auto& s : r.studies)
    out["materials"][s.name] = studyJson(s);
  r.json = out.dump(1);
  r.report.add("kernel_report.md", r.markdown);
  r.report.add("kernel_report.json", r.json);
  addCharts(r.studies, r.report);
  return r;
}

}  // namespace tissue::studies
