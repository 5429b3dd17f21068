// tissue-sim raymarch-study: where ray-marched subsurface texture mapping fails, in numbers
// and images: grazing views, high curvature, large deformation and few samples. Computed with
// the CPU model (tissue::subsurface), which the GL tests show equals the shader; the
// reference is the mesh-mode march (light entry on the actual mesh) with many samples.
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "command.h"
#include "output.h"
#include "raymarch_scene.h"
#include "tissue/studies/raymarch_study.h"

namespace tissue::sim_app {
namespace {

struct StudyOptions {
  int width = 120;             // pixels
  int height = 90;             // pixels
  int referenceSamples = 100;  // samples of the reference and of the plane-mode image
  std::string images;          // folder for error images, empty = none
};

struct Case {
  const char* name;
  const char* mesh;  // data/meshes/<mesh>.obj
  float pokeDepthMm;
  const char* what;
};

Result<nlohmann::json> study(const Case& c, const StudyOptions& o) {
  auto loaded = loadRayMarchScene(dataDir() / "meshes" / (std::string(c.mesh) + ".obj"),
                                  float(o.width) / float(o.height), true);
  if (!loaded) return loaded.error();
  RayMarchScene& scene = *loaded;
  if (c.pokeDepthMm > 0.0f) {
    if (auto poked = pokeScene(scene, 0.02, c.pokeDepthMm); !poked) return poked.error();
  }
  studies::RayMarchStudyConfig config;
  config.width = o.width;
  config.height = o.height;
  config.referenceSamples = o.referenceSamples;
  config.radianceScale = kRayMarchRadianceScale;
  config.background = kRayMarchBackground;
  const studies::RayMarchStudy r = studies::studyRayMarch(meshView(scene), scene.material.stack, scene.lights,
                                                          pinholeOf(scene.camera), config);
  nlohmann::json row;
  row["case"] = c.name;
  row["what"] = c.what;
  row["plane_rms"] = r.planes.all;
  row["plane_rms_grazing"] = r.planes.grazing;
  row["plane_rms_frontal"] = r.planes.frontal;
  row["samples10_rms"] = r.few.all;
  row["samples10_rms_grazing"] = r.few.grazing;
  row["samples10_rms_frontal"] = r.few.frontal;
  if (!o.images.empty()) {
    const std::filesystem::path dir = o.images;
    const std::string stem = std::string("raymarch_fail_") + c.name;
    for (auto [suffix, img] :
         {std::pair{"_reference.png", &r.reference}, std::pair{"_10samples.png", &r.fewImage}})
      if (auto w = writePng(dir / (stem + suffix), *img); !w) return w.error();
    if (auto w = writePng(dir / (stem + "_plane_error_x8.png"),
                          studies::differenceImage(r.planesImage, r.reference));
        !w)
      return w.error();
  }
  return row;
}

int run(const StudyOptions& o, const GlobalOptions& global) {
  const Case cases[] = {
      {"patch", "patch", 0.0f, "nearly flat (250 mm dome), rest shape"},
      {"liver", "liver", 0.0f, "liver top, rest shape"},
      {"liver_poke8", "liver", 8.0f, "liver poked 8 mm deep"},
      {"liver_poke16", "liver", 16.0f, "liver poked 16 mm deep (large deformation)"},
      {"tube", "tube", 0.0f, "bowel tube, radius 8-12 mm (high curvature)"},
  };
  nlohmann::json rows = nlohmann::json::array();
  for (const Case& c : cases) {
    auto row = study(c, o);
    if (!row) return fail("raymarch-study", std::string(c.name) + ": " + row.error().message);
    rows.push_back(*row);
  }
  nlohmann::json out;
  out["width"] = o.width;
  out["height"] = o.height;
  out["reference_samples"] = o.referenceSamples;
  out["cases"] = rows;
  if (global.json) {
    printResult(global, out);
    return 0;
  }
  std::printf("%-13s %9s %9s %9s %9s %9s %9s\n", "case", "plane", "p.grazing", "p.frontal", "10 smp",
              "10 graz", "10 front");
  for (const auto& r : rows)
    std::printf("%-13s %9.4f %9.4f %9.4f %9.4f %9.4f %9.4f\n", r["case"].get<std::string>().c_str(),
                r["plane_rms"].get<double>(), r["plane_rms_grazing"].get<double>(),
                r["plane_rms_frontal"].get<double>(), r["samples10_rms"].get<double>(),
                r["samples10_rms_grazing"].get<double>(), r["samples10_rms_frontal"].get<double>());
  return 0;
}

}  // namespace

void registerRayMarchStudyCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto o = std::make_shared<StudyOptions>();
  auto* cmd = app.add_subcommand("raymarch-study",
                                 "where ray-marched subsurface scattering fails: grazing views, curvature, "
                                 "deformation, few samples (RMS against the mesh-entry reference)");
  cmd->add_option("--width", o->width, "image width, pixels (default 120)");
  cmd->add_option("--height", o->height, "image height, pixels (default 90)");
  cmd->add_option("--reference-samples", o->referenceSamples, "samples of the reference (default 100)");
  cmd->add_option("--images", o->images, "folder for reference, 10-sample and error images (must exist)");
  cmd->callback([o, &global, &exitCode] { exitCode = run(*o, global); });
}

}  // namespace tissue::sim_app
