#pragma once
/// \file
/// `tissue-sim kernel-report`: Freude 2014's kernel comparisons (Tables 6.3 and 6.5, and the
/// image-space errors) for Apple, Marble, Ketchup, Skin1 and Wholemilk, next to the thesis's
/// published sums, as Markdown tables, JSON and two charts. GL-free.

#include <array>
#include <string>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/optics/materials.h"
#include "tissue/studies/kernel_study.h"
#include "tissue/studies/report.h"

namespace tissue::studies {

/// The report's materials (Jensen 2001's names), in the order of the thesis's tables.
inline constexpr std::array<const char*, 5> kKernelReportMaterials = {"Apple", "Marble", "Ketchup", "Skin1",
                                                                      "Wholemilk"};

/// The four models of Freude 2014, Table 6.3, by their labels in the study (kernel_study.h).
inline constexpr std::array<const char*, 4> kFreude2014Table63Models = {"SVD1", "Pre-int.", "Guided k=1",
                                                                        "Manual"};

/// Freude 2014, Table 6.3: per material, the sum over RGB of the kernel-space error of each of
/// kFreude2014Table63Models, normalised to the table's largest RGB error.
struct Freude2014Table63Row {
  const char* material;
  std::array<double, 4> sums;
};
inline constexpr std::array<Freude2014Table63Row, 5> kFreude2014Table63 = {
    {{"Apple", {0.181, 0.384, 0.440, 0.330}},
     {"Marble", {0.124, 0.263, 0.299, 0.226}},
     {"Ketchup", {0.379, 0.863, 0.469, 1.833}},
     {"Skin1", {0.192, 0.442, 0.479, 0.557}},
     {"Wholemilk", {0.123, 0.258, 0.296, 0.243}}}};

/// Freude 2014, Table 6.5 (Skin1, the Head scene): sums over RGB of the normalised image-space
/// error of SVD rank-k and d'Eon k-Gaussian kernels, k = 1..6.
inline constexpr std::array<double, 6> kFreude2014Table65Svd = {1.481, 0.852, 0.432, 0.272, 0.141, 0.088};
inline constexpr std::array<double, 6> kFreude2014Table65Deon = {1.679, 1.406, 0.949, 0.557, 0.330, 0.214};

/// Table 6.3's form: per material (a row) and model (SVD1, Pre-int., Guided k=1, Manual, SVD1 N.,
/// d'Eon 1, Jimenez), "R G B (**sum**; thesis T)", each RGB kernel-space RMS divided by `scale`.
Table kernelSpaceTable(const std::vector<KernelStudy>& studies, double scale);
/// Table 6.3's normaliser: the largest RGB kernel-space RMS of the four thesis models over `studies`.
double kernelSpaceScale(const std::vector<KernelStudy>& studies);

/// Table 6.5's form on `signal`: per k = 1..6, Skin1's SVD and d'Eon errors divided by `scale`
/// with the thesis's sums, then every other material's sums (x 1e-3). Needs Skin1 in `studies`.
Table rankTable(const std::vector<KernelStudy>& studies, const std::string& signal, double scale);
/// Table 6.5's normaliser: Skin1's largest RGB image-space RMS on `signal` over SVD and d'Eon 1..6.
double rankScale(const std::vector<KernelStudy>& studies, const std::string& signal);

/// What the report found and what it writes.
struct KernelReport {
  std::vector<KernelStudy> studies;
  std::string markdown;  ///< kernel_report.md
  std::string json;      ///< kernel_report.json: {"materials": {NAME: {"grid_cell_mm", "models": ...}}}
  /// kernel_report.md, kernel_report.json, svd_vs_deon_skin1.png, kernels_skin1_red.png.
  Report report;
};

/// Runs studyKernels on each of `materials` (kKernelReportMaterials, Skin1 among them) and
/// assembles the report.
Result<KernelReport> kernelReport(const std::vector<optics::ScatteringMaterial>& materials);

}  // namespace tissue::studies
