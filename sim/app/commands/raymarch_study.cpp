// tissue-sim raymarch-study: where ray-marched subsurface texture mapping fails, in numbers and
// images: grazing views, high curvature, large deformation and few samples, on the CPU model
// against the mesh-entry march with many samples. The study, its cases and its report are
// tissue::studies' (studies/raymarch_study.h); this command parses, writes and prints.

#include "tissue/studies/raymarch_study.h"
#include "../organ_data.h"
#include "cli_options.h"
#include "command.h"
#include "output.h"
#include "report_output.h"

namespace tissue::sim_app {
namespace {

struct StudyOptions {
  studies::RayMarchStudyConfig config;
  ReportPlaces places;  // --out (report and images), --images
};

int run(const StudyOptions& o, const GlobalOptions& global) {
  const char* cmd = "raymarch-study";
  auto study =
      studies::runRayMarchStudy(dataOrganNamed, o.config, !o.places.out.empty() || !o.places.images.empty());
  if (!study) return fail(cmd, study.error().message);
  return finishStudy(cmd, std::move(study->output), o.places, global);
}

}  // namespace

void registerRayMarchStudyCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto o = std::make_shared<StudyOptions>();
  auto* cmd = app.add_subcommand("raymarch-study",
                                 "where ray-marched subsurface scattering fails: grazing views, curvature, "
                                 "deformation, few samples (RMS against the mesh-entry reference)");
  addImageSizeOptions(cmd, o->config.width, o->config.height);
  cmd->add_option("--reference-samples", o->config.referenceSamples,
                  "samples of the reference (default 100)");
  cmd->add_option("--images", o->places.images, "folder for reference, 10-sample and error images (created)");
  cmd->add_option("--out", o->places.out,
                  "folder for the report: raymarch_study.md, .csv, .json and the images");
  cmd->callback([o, &global, &exitCode] { exitCode = run(*o, global); });
}

}  // namespace tissue::sim_app
