#pragma once
/// \file
/// Where the GL benches' and studies' reports (studies::Report) go, as their options ask.

#include <string>

#include "command.h"
#include "tissue/core/result.h"
#include "tissue/studies/report.h"

namespace tissue::sim_app {

/// Folders and files a command's options name for its report; empty: not asked for.
struct ReportPlaces {
  std::string out;     ///< the report's text files (and its images and charts unless named below)
  std::string images;  ///< a folder for its images
  std::string chart;   ///< the file of its one chart
  std::string image;   ///< the file of its one image
};

/// Writes `report`: text files only with `out`; images into `images`, to `image`, else into `out`;
/// the chart to `chart`, else into `out`. What has no place is dropped.
Result<void> writeReportTo(studies::Report report, const ReportPlaces& places);

/// A study's or bench's end: writes its report (writeReportTo), prints its JSON with --json, else
/// its summary, and returns the exit code (errors as `command`'s one line on stderr).
int finishStudy(const char* command, studies::StudyOutput output, const ReportPlaces& places,
                const GlobalOptions& global);

}  // namespace tissue::sim_app
