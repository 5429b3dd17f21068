#pragma once
/// \file
/// A study's or bench's report: Markdown and CSV tables, JSON, and line charts, written into one
/// folder, each file atomically (a run interrupted part-way leaves every earlier file whole).
/// tissue-sim's studies, the benches and any host that reruns them share it, so that a command
/// only parses its arguments, calls the study and prints.

#include <filesystem>
#include <string>
#include <vector>

#include "tissue/core/image.h"
#include "tissue/core/result.h"
#include "tissue/inspect/chart.h"

namespace tissue::studies {

/// A table of text cells: one header row, then rows of as many cells (short rows are padded).
struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

/// The table in GitHub Markdown ("| a | b |", a rule, the rows), ending in a newline.
std::string markdownTable(const Table& table);
/// The table as CSV (RFC 4180: cells with a comma, quote or newline are quoted), one line a row.
std::string csvTable(const Table& table);

/// `value` with `digits` after the point ("%.*f"); "-" for NaN.
std::string fixed(double value, int digits = 3);
/// `value` with `digits` significant digits ("%.*g"); "-" for NaN.
std::string general(double value, int digits = 6);

/// One text file of a report, named relative to the report's folder.
struct ReportFile {
  std::string name;  ///< e.g. "stability.md"
  std::string text;
};

/// One chart of a report: a PNG drawn by inspect::writeLineChart.
struct ReportChart {
  std::string name;  ///< e.g. "stability.png"
  inspect::ChartSettings settings;
  std::vector<inspect::ChartSeries> series;
};

/// One image of a report: a PNG (writePng).
struct ReportImage {
  std::string name;  ///< e.g. "raymarch_100.png"
  Image8 image;
};

/// What a study writes.
struct Report {
  std::vector<ReportFile> files;
  std::vector<ReportChart> charts;
  std::vector<ReportImage> images;
  /// Adds a text file.
  void add(std::string name, std::string text) { files.push_back({std::move(name), std::move(text)}); }
};

/// What a study or bench hands its caller besides its numbers: the report to write, its JSON
/// object as text (also one of the report's files) for --json, and a short text summary (its
/// main Markdown table) for a terminal.
struct StudyOutput {
  Report report;
  std::string json;
  std::string summary;
};

/// Creates `dir` and writes the report's files and images (each atomically), then its charts.
/// Fails on the first file, image or chart it cannot write, naming it; charts fail without VTK or
/// an X server (inspect::writeLineChart), after every text file and image is written. A name may
/// be a path (relative to `dir`, or absolute); its folders are created.
Result<void> writeReport(const std::filesystem::path& dir, const Report& report);

}  // namespace tissue::studies
