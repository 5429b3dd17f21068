// tissue-sim render [--mesh FILE] --out IMAGE.png [--method lit|separable|texture-space|ray-march|parallax]
// [method options]: one image of an organ with one shading method, through the scene module
// (tissue::scene::Scene: the organ's assets, its material file's textures, the method's settings
// and the framing are the library's).
#include <filesystem>
#include <optional>

#include "../organ_data.h"
#include "cli_options.h"
#include "command.h"
#include "gl_environment.h"
#include "output.h"
#include "tissue/scene/scene.h"
#include "tissue/studies/demo_run.h"
#include "tissue/studies/render_summary.h"

namespace tissue::sim_app {
namespace {

struct RenderOptions {
  std::string mesh;  // empty: data/meshes/liver.obj
  std::string method = "lit";
  std::string material;  // data/materials/<name>.json; default: the mesh's stem, when there is one
  std::string out;
  int width = 1024;                                                // pixels
  int height = 768;                                                // pixels
  float scale = 1.0f;                                              // mm per file unit
  int samples = 4;                                                 // MSAA
  scene::MethodChoices choices{.samples = 50, .adaptive = false};  // the rest: the main job's
};

/// The options behind a method's settings, for its errors.
std::string methodOptions(const RenderOptions& o, render::ShadingMethod m) {
  const auto& c = o.choices;
  using render::ShadingMethod;
  if (m == ShadingMethod::Separable)
    return " --kernel " + c.kernel + " --taps " + std::to_string(c.taps) + " --rank " +
           std::to_string(c.rank);
  if (m == ShadingMethod::TextureSpace)
    return " --gaussians " + std::to_string(c.gaussians) + " --map-size " + std::to_string(c.mapSize);
  return "";
}

int run(const RenderOptions& o, const GlobalOptions& global) {
  const char* cmd = "render";
  if (o.width <= 0 || o.height <= 0) return fail(cmd, "--width and --height must be positive pixels");
  auto method = scene::parseShadingMethod(o.method);
  if (!method) return fail(cmd, "--" + method.error().message);
  // The scene on the app's context: the renderer's settings, the project's material files.
  auto context = createAppContext({}, false);
  if (!context) return fail(cmd, context.error().message);
  scene::SceneSettings settings;
  settings.renderer = {.shaders = shaderSettingsFromEnvironment(), .samples = o.samples, .gpuTimers = true};
  settings.renderer.finishPasses = *method == render::ShadingMethod::RayMarch;  // its pass timed to the end
  settings.materials = dataMaterialOptions();
  settings.materialsDir = dataDir() / "materials";
  settings.methods = o.choices;
  auto made = scene::Scene::create((*context)->procAddressFunction(), settings);
  if (!made) return fail(cmd, made.error().message);
  scene::Scene& s = *made;
  scene::OrganDesc desc{.mesh = meshOrDefault(o.mesh), .method = *method, .meshScaleToMm = o.scale};
  if (!o.material.empty()) desc.material = dataDir() / "materials" / (o.material + ".json");
  auto organ = s.addOrgan(desc);
  if (!organ)
    return fail(cmd, "--method " + o.method + methodOptions(o, *method) + ": " + organ.error().message);
  s.setShadows(true);                              // shadows, and the separable method's transmission
  std::optional<mesh::DeformableSurface> surface;  // ray marching: the ray-march studies' framing
  if (*method == render::ShadingMethod::RayMarch) {
    auto rest = mesh::DeformableSurface::create(s.assets(*organ).mesh, s.assets(*organ).planes);
    if (!rest) return fail(cmd, rest.error().message);
    surface.emplace(std::move(*rest));
    if (auto framed = studies::frameForRayMarch(s, *surface, float(o.width) / float(o.height), false);
        !framed)
      return fail(cmd, framed.error().message);
  }
  // A first frame allocates the targets and compiles the shaders; the second is timed.
  auto first = s.renderImage(o.width, o.height);
  if (!first) return fail(cmd, first.error().message);
  const double firstMs = s.renderer().lastTimings().totalCpuMs;
  auto image = s.renderImage(o.width, o.height);
  if (!image) return fail(cmd, image.error().message);
  if (auto w = writePng(o.out, *image); !w) return fail(cmd, w.error().message);

  auto out = nlohmann::json::parse(
      studies::organRenderJson(s.assets(*organ), *method, o.choices, s.renderer().lastTimings()));
  out.update({{"out", o.out},
              {"width", o.width},
              {"height", o.height},
              {"gl_context", (*context)->info().backend},
              {"gl_renderer", (*context)->info().renderer},
              {"first_frame_ms", firstMs},
              {"samples", o.samples}});
  printResult(global, out);
  return 0;
}

}  // namespace

void registerRenderCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto opts = std::make_shared<RenderOptions>();
  scene::MethodChoices& c = opts->choices;
  auto* cmd = app.add_subcommand("render", "render a mesh with one shading method to a PNG");
  cmd->add_option("--mesh", opts->mesh, "mesh file (OBJ, PLY, OFF, STL; default data/meshes/liver.obj)");
  cmd->add_option("--method", opts->method,
                  "shading method: lit, separable, texture-space, ray-march or parallax");
  cmd->add_option(
      "--material", opts->material,
      "data/materials/<NAME>.json: optics and textures (default: the mesh's name, when there is one)");
  cmd->add_option("--out", opts->out, "output PNG (written atomically)")->required();
  addImageSizeOptions(cmd, opts->width, opts->height);
  cmd->add_option("--scale", opts->scale, "mm per file unit (default 1)");
  cmd->add_option("--samples", opts->samples, "MSAA samples (default 4; 0 = off)");
  cmd->add_option("--kernel", c.kernel,
                  "separable kernel model: svd, preintegrated, guided, manual, deon, jimenez");
  cmd->add_option("--taps", c.taps, "separable kernel taps per 1D pass (odd, default 17)");
  cmd->add_option("--rank", c.rank,
                  "separable kernel components: svd rank or deon Gaussian count, 1..8 (default 1)");
  cmd->add_option("--gaussians", c.gaussians,
                  "texture-space: Gaussians fitted to the material's profile (default 6)");
  cmd->add_option("--map-size", c.mapSize, "texture-space: T_max, irradiance map texels (default 1024)");
  cmd->add_flag(
      "--no-cull", [&c](std::int64_t) { c.cull = false; }, "texture-space and parallax: no culled map");
  cmd->add_flag(
      "--no-clip", [&c](std::int64_t) { c.clip = false; }, "texture-space and parallax: no clipped map");
  cmd->add_flag(
      "--no-depth-size", [&c](std::int64_t) { c.depthSize = false; },
      "texture-space: no depth-based map size");
  cmd->add_option("--layer-depth", c.parallaxDepthMm, "parallax: inner layer depth, mm (default 1.5)");
  cmd->add_option("--refractive-index", c.refractiveIndex,
                  "parallax: n_inside / n_outside (default: the material's ior; 1 = Oat 2006)");
  cmd->add_option("--blur-radius", c.lightmap.blurRadiusMm,
                  "parallax: lightmap Poisson-disc radius, mm (default 4)");
  cmd->add_option("--blur-passes", c.lightmap.blurPasses, "parallax: lightmap blur passes (default 3)");
  cmd->add_option("--lightmap-size", c.lightmap.size,
                  "parallax: irradiance pass texels a side (default 1024)");
  cmd->add_option("--lightmap-reduction", c.lightmap.reduction,
                  "parallax: the blurred lightmap is size / reduction texels (1, 2, 4, 8; default 4)");
  cmd->add_option("--march-samples", c.samples, "ray-march: samples per pixel (default 50)");
  cmd->add_flag("--adaptive", c.adaptive, "ray-march: choose the sample count per pixel");
  cmd->callback([opts, &global, &exitCode] { exitCode = run(*opts, global); });
}

}  // namespace tissue::sim_app
