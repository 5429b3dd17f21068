// tissue-sim parallax-study --out DIR [--json]: where layered parallax (Oat 2006; Norberg 2010
// §2.2) fails, in numbers and images. The method looks the inner layer up at the tangent-plane
// offset of eq. 15-18 (layers "flat and parallel in tangent space"); the truth is the refracted
// view ray intersected with the actual inner layer, the surface pushed in by the depth along -N.
// Per view angle, on a plane (control), a sphere, the liver and the bowel tube: the distance (mm,
// on the outer surface) between the texel the method reads and the true one, and the fraction of
// rays that leave the surface before reaching the layer (the method still shows a layer there).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>

#include "../parallax_scene.h"
#include "command.h"
#include "output.h"
#include "tissue/studies/parallax_study.h"

namespace tissue::sim_app {
namespace {

struct StudyOptions {
  std::string out;          // folder for the images (created)
  int samplePoints = 1500;  // surface points per mesh and angle
  int imageWidth = 384;     // pixels
  int imageHeight = 288;    // pixels
};

Result<studies::ParallaxSurface> organSurface(const char* name, const char* what) {
  auto organ = loadTsdOrgan(dataDir() / "meshes" / (std::string(name) + ".obj"), 1.0f);
  if (!organ) return organ.error();
  return studies::ParallaxSurface{name, what, organ->mesh.positions, organ->normals, organ->mesh.triangles,
                                  {}};
}

nlohmann::json cellJson(const studies::ParallaxCell& c) {
  nlohmann::json j;
  j["samples"] = c.samples;
  j["reached"] = std::size_t(c.reached);
  j["miss_fraction"] = c.missFraction;
  j["mean_error_mm"] = c.meanErrorMm;
  j["p95_error_mm"] = c.p95ErrorMm;
  j["max_error_mm"] = c.maxErrorMm;
  j["mean_parallax_offset_mm"] = c.meanParallaxOffsetMm;
  j["mean_true_offset_mm"] = c.meanTrueOffsetMm;
  j["view_angle_deg"] = c.viewAngleDeg;
  return j;
}

// Images of the patch seen at angles from its normal: the inner vessels' shift and, at grazing
// angles, the eq. 19 fade to the outer layer.
Result<nlohmann::json> renderImages(const StudyOptions& o) {
  ParallaxOptions options;
  options.layerDepthMm = 3.0f;
  options.settings.opacity = 0.3f;
  auto loaded = loadParallaxScene(dataDir() / "meshes" / "patch.obj", 1.0f,
                                  float(o.imageWidth) / float(o.imageHeight), 4, options);
  if (!loaded) return loaded.error();
  ParallaxScene& p = *loaded;
  p.scene.lights[0].type = render::LightType::Directional;
  p.scene.lights[0].direction = {-0.3f, -0.2f, -1.0f};
  nlohmann::json files = nlohmann::json::array();
  for (const float angle : {0.0f, 45.0f, 75.0f, 85.0f}) {
    const float a = angle * std::numbers::pi_v<float> / 180.0f;
    p.scene.camera =
        render::frameBoundingBox(p.organ.lo, p.organ.hi, float(o.imageWidth) / float(o.imageHeight),
                                 {-std::sin(a), 0.0f, -std::cos(a)});
    // Closer than the bounding-sphere fit: the patch fills the frame seen from above.
    render::Camera& c = p.scene.camera;
    c.eye = {c.target.x + 0.6f * (c.eye.x - c.target.x), c.target.y + 0.6f * (c.eye.y - c.target.y),
             c.target.z + 0.6f * (c.eye.z - c.target.z)};
    c.nearMm *= 0.3f;
    auto image = p.renderer->renderImage(p.scene, o.imageWidth, o.imageHeight);
    if (!image) return image.error();
    const auto file =
        std::filesystem::path(o.out) / ("parallax_patch_" + std::to_string(int(angle)) + "deg.png");
    if (auto w = writePng(file, *image); !w) return w.error();
    files.push_back(file.string());
  }
  return files;
}

int run(const StudyOptions& o, const GlobalOptions& global) {
  const char* cmd = "parallax-study";
  std::error_code ec;
  std::filesystem::create_directories(o.out, ec);
  if (ec) return fail(cmd, "--out " + o.out + ": cannot create the folder: " + ec.message());
  std::vector<studies::ParallaxSurface> surfaces = {studies::parallaxPlane(100),
                                                    studies::parallaxSphere(40.0, 160)};
  for (auto [name, what] : {std::pair{"liver", "liver (rest shape; curvature radii ~30-100 mm)"},
                            std::pair{"tube", "bowel tube, radius 8-12 mm (high curvature)"}}) {
    auto s = organSurface(name, what);
    if (!s) return fail(cmd, std::string(name) + ": " + s.error().message);
    surfaces.push_back(std::move(*s));
  }
  studies::ParallaxStudyConfig config;
  config.samplePoints = o.samplePoints;
  nlohmann::json rows = nlohmann::json::array();
  for (const studies::ParallaxRow& r : studies::studyParallax(surfaces, config)) {
    nlohmann::json row;
    row["surface"] = r.surface;
    row["what"] = r.what;
    row["depth_mm"] = r.depthMm;
    row["refractive_index"] = r.refractiveIndex;
    nlohmann::json cells = nlohmann::json::array();
    for (const studies::ParallaxCell& c : r.cells)
      cells.push_back(cellJson(c));
    row["angles"] = cells;
    rows.push_back(row);
  }
  auto images = renderImages(o);
  if (!images) return fail(cmd, "images: " + images.error().message);
  nlohmann::json out;
  out["results"] = rows;
  out["images"] = *images;
  out["max_transmission_mm"] = config.maxTransmissionMm;
  if (global.json) {
    printResult(global, out);
    return 0;
  }
  std::printf("mean lookup error, mm (miss %% where rays leave before the layer)\n%-11s %5s %4s", "surface",
              "d mm", "n");
  for (const float a : config.viewAnglesDeg)
    std::printf(" %13.0f", double(a));
  std::printf("\n");
  for (const auto& r : rows) {
    std::printf("%-11s %5.1f %4.1f", r["surface"].get<std::string>().c_str(), r["depth_mm"].get<double>(),
                r["refractive_index"].get<double>());
    for (const auto& c : r["angles"]) {  // "-": no ray reached the layer
      const double miss = 100.0 * c["miss_fraction"].get<double>();
      if (c["reached"].get<int>() == 0)
        std::printf(" %6s (%3.0f%%)", "-", miss);
      else
        std::printf(" %6.3f (%3.0f%%)", c["mean_error_mm"].get<double>(), miss);
    }
    std::printf("\n");
  }
  for (const auto& f : *images)
    std::printf("wrote %s\n", f.get<std::string>().c_str());
  return 0;
}

}  // namespace

void registerParallaxStudyCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto o = std::make_shared<StudyOptions>();
  auto* cmd = app.add_subcommand("parallax-study",
                                 "where layered parallax fails: lookup error (mm) against the refracted ray "
                                 "meeting the true inner layer, per view angle, on flat and curved meshes");
  cmd->add_option("--out", o->out, "folder for the images (created)")->required();
  cmd->add_option("--points", o->samplePoints, "surface points per mesh and angle (default 1500)");
  cmd->callback([o, &global, &exitCode] { exitCode = run(*o, global); });
}

}  // namespace tissue::sim_app
