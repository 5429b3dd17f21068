// tissue-sim parallax-study --out DIR [--json]: where layered parallax (Oat 2006; Norberg 2010
// §2.2) fails, in numbers and images: the lookup error (mm) against the refracted view ray meeting
// the true inner layer, per view angle, on a plane, a sphere, the liver and the bowel tube. The
// study and its report are tissue::studies' (studies/parallax_scene.h); this command makes the
// context, writes the report and prints.

#include "../organ_data.h"
#include "command.h"
#include "gl_environment.h"
#include "output.h"
#include "report_output.h"
#include "tissue/studies/parallax_scene.h"

namespace tissue::sim_app {
namespace {

struct StudyOptions {
  ReportPlaces places;  // --out: the report and the images (created)
  studies::ParallaxStudyRun run;
};

int run(StudyOptions o, const GlobalOptions& global) {
  const char* cmd = "parallax-study";
  auto context = createAppContext({}, false);
  if (!context) return fail(cmd, context.error().message);
  auto renderer = createAppRenderer(**context, 4, true);
  if (!renderer) return fail(cmd, renderer.error().message);
  o.run.imageFolder = o.places.out;
  auto study = studies::runParallaxStudy(*renderer, dataOrganNamed, o.run);
  if (!study) return fail(cmd, study.error().message);
  return finishStudy(cmd, std::move(study->output), o.places, global);
}

}  // namespace

void registerParallaxStudyCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto o = std::make_shared<StudyOptions>();
  auto* cmd = app.add_subcommand("parallax-study",
                                 "where layered parallax fails: lookup error (mm) against the refracted ray "
                                 "meeting the true inner layer, per view angle, on flat and curved meshes");
  cmd->add_option("--out", o->places.out,
                  "folder for the report (parallax_study.md, .csv, .json) and the images (created)")
      ->required();
  cmd->add_option("--points", o->run.study.samplePoints, "surface points per mesh and angle (default 1500)");
  cmd->callback([o, &global, &exitCode] { exitCode = run(*o, global); });
}

}  // namespace tissue::sim_app
