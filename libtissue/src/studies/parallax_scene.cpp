// An organ ready for layered parallax and its one-object scene (parallax_scene.h).
#include "tissue/studies/parallax_scene.h"

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numbers>
#include <utility>

namespace tissue::studies {

Result<ParallaxOrgan> loadParallaxOrgan(const scene::OrganSource& source) {
  auto assets = scene::loadOrganAssets(source);
  if (!assets) return assets.error();
  ParallaxOrgan out;
  out.organ = tsdOrganOf(std::move(assets->mesh));
  out.organ.atlas = assets->atlas;
  out.organ.charts = assets->atlasCharts;
  // The layer textures live in the mesh's own UV space (loadOrganAssets drops them with the atlas).
  out.textured = !assets->atlas && assets->innerBase.has_value();
  if (out.textured) {
    out.baseColor = std::move(assets->baseColor);
    out.normalMap = std::move(assets->normalMap);
    out.opacity = std::move(assets->opacity);
    out.innerBase = std::move(assets->innerBase);
  }
  return out;
}

Result<render::Scene> makeParallaxScene(render::Renderer& renderer, const ParallaxOrgan& organ,
                                        const ParallaxOptions& options, float aspect) {
  auto mesh = renderer.createMesh(organ.organ.arrays());
  if (!mesh) return mesh.error();
  render::SceneObject object;
  object.mesh = *mesh;
  render::ParallaxSettings s = options.settings;
  s.layers = {render::ParallaxLayer{{}, options.layerDepthMm, 1.0f}};
  if (organ.textured) {
    for (auto [image, handle] :
         {std::pair{&organ.baseColor, &object.baseColor}, std::pair{&organ.normalMap, &object.normalMap},
          std::pair{&organ.opacity, &s.opacityMap}, std::pair{&organ.innerBase, &s.layers[0].base}}) {
      if (!image->has_value()) continue;
      auto texture = renderer.createTexture(**image);
      if (!texture) return texture.error();
      *handle = *texture;
    }
  }
  object.method = s;
  render::Scene scene;
  scene.camera = render::frameBoundingBox(organ.organ.lo, organ.organ.hi, aspect);
  scene.objects = {object};
  return scene;
}

namespace {

nlohmann::json cellJson(const ParallaxCell& c) {
  return {{"samples", c.samples},
          {"reached", c.reached},
          {"miss_fraction", c.missFraction},
          {"mean_error_mm", c.meanErrorMm},
          {"p95_error_mm", c.p95ErrorMm},
          {"max_error_mm", c.maxErrorMm},
          {"mean_parallax_offset_mm", c.meanParallaxOffsetMm},
          {"mean_true_offset_mm", c.meanTrueOffsetMm},
          {"view_angle_deg", c.viewAngleDeg}};
}

// The patch seen from angles to its normal, a little closer than the bounding-sphere fit so that
// it fills the frame seen from above.
Result<std::vector<ReportImage>> patchImages(render::Renderer& renderer, scene::OrganSource source,
                                             const ParallaxStudyRun& run) {
  if (!std::filesystem::exists(source.material)) source.material.clear();  // the default organ, untextured
  auto organ = loadParallaxOrgan(source);
  if (!organ) return organ.error();
  const float aspect = float(run.imageWidth) / float(run.imageHeight);
  ParallaxOptions options;
  options.layerDepthMm = 3.0f;
  options.settings.opacity = 0.3f;
  auto scene = makeParallaxScene(renderer, *organ, options, aspect);
  if (!scene) return scene.error();
  scene->lights[0].type = render::LightType::Directional;
  scene->lights[0].direction = {-0.3f, -0.2f, -1.0f};
  std::vector<ReportImage> out;
  for (const float angle : {0.0f, 45.0f, 75.0f, 85.0f}) {
    const float a = angle * std::numbers::pi_v<float> / 180.0f;
    render::Camera& c = scene->camera;
    c = render::frameBoundingBox(organ->organ.lo, organ->organ.hi, aspect,
                                 {-std::sin(a), 0.0f, -std::cos(a)});
    c.eye = {c.target.x + 0.6f * (c.eye.x - c.target.x), c.target.y + 0.6f * (c.eye.y - c.target.y),
             c.target.z + 0.6f * (c.eye.z - c.target.z)};
    c.nearMm *= 0.3f;
    auto image = renderer.renderImage(*scene, run.imageWidth, run.imageHeight);
    if (!image) return image.error();
    out.push_back({"parallax_patch_" + std::to_string(int(angle)) + "deg.png", std::move(*image)});
  }
  return out;
}

}  // namespace

Result<ParallaxStudyResult> runParallaxStudy(
    render::Renderer& renderer, const std::function<scene::OrganSource(const std::string&)>& organSource,
    const ParallaxStudyRun& run) {
  std::vector<ParallaxSurface> surfaces = {parallaxPlane(100), parallaxSphere(40.0, 160)};
  for (auto [name, what] : {std::pair{"liver", "liver (rest shape; curvature radii ~30-100 mm)"},
                            std::pair{"tube", "bowel tube, radius 8-12 mm (high curvature)"}}) {
    const scene::OrganSource source = organSource(name);
    auto organ = loadTsdOrgan(source.mesh, source.meshScaleToMm);
    if (!organ) return Error{std::string(name) + ": " + organ.error().message};
    surfaces.push_back({name, what, organ->mesh.positions, organ->normals, organ->mesh.triangles, {}});
  }
  ParallaxStudyResult out;
  out.rows = studyParallax(surfaces, run.study);
  auto images = patchImages(renderer, organSource("patch"), run);
  if (!images) return Error{"images: " + images.error().message};
  nlohmann::json rows = nlohmann::json::array(), files = nlohmann::json::array();
  Table table{{"surface", "d mm", "n"}, {}};
  Table csv{
      {"surface", "depth_mm", "refractive_index", "view_angle_deg", "samples", "reached", "miss_fraction",
       "mean_error_mm", "p95_error_mm", "max_error_mm", "mean_parallax_offset_mm", "mean_true_offset_mm"},
      {}};
  for (const float a : run.study.viewAnglesDeg)
    table.header.push_back(fixed(a, 0) + " deg");
  for (const ParallaxRow& r : out.rows) {
    nlohmann::json cells = nlohmann::json::array();
    table.rows.push_back({r.surface, fixed(r.depthMm, 1), fixed(r.refractiveIndex, 1)});
    for (const ParallaxCell& c : r.cells) {
      cells.push_back(cellJson(c));
      const std::string miss =
          " (" + fixed(100.0 * c.missFraction, 0) + "%)";  // "-": no ray reached the layer
      table.rows.back().push_back((c.reached == 0 ? std::string("-") : fixed(c.meanErrorMm, 3)) + miss);
      csv.rows.push_back({r.surface, general(r.depthMm), general(r.refractiveIndex), general(c.viewAngleDeg),
                          std::to_string(c.samples), std::to_string(c.reached), general(c.missFraction),
                          general(c.meanErrorMm), general(c.p95ErrorMm), general(c.maxErrorMm),
                          general(c.meanParallaxOffsetMm), general(c.meanTrueOffsetMm)});
    }
    rows.push_back({{"surface", r.surface},
                    {"what", r.what},
                    {"depth_mm", r.depthMm},
                    {"refractive_index", r.refractiveIndex},
                    {"angles", cells}});
  }
  for (const ReportImage& i : *images)
    files.push_back((std::filesystem::path(run.imageFolder) / i.name).string());
  const nlohmann::json json{
      {"results", rows}, {"images", files}, {"max_transmission_mm", run.study.maxTransmissionMm}};
  out.output.json = json.dump(2);
  out.output.summary =
      "mean lookup error, mm (miss % where rays leave before the layer)\n\n" + markdownTable(table);
  out.output.report.add(
      "parallax_study.md",
      "# Where layered parallax fails\n\nThe distance (mm, on the outer surface) between the "
      "texel the method reads (Oat 2006; Norberg 2010 eq. 15-18) and the one the refracted view "
      "ray meets on the true inner layer, " +
          std::to_string(run.study.samplePoints) + " points per surface and angle.\n\n" + out.output.summary);
  out.output.report.add("parallax_study.csv", csvTable(csv));
  out.output.report.add("parallax_study.json", out.output.json + "\n");
  out.output.report.images = std::move(*images);
  return out;
}

}  // namespace tissue::studies
