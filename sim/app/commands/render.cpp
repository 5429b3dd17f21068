// tissue-sim render [--mesh FILE] --out IMAGE.png [--method lit|separable|texture-space|raymarch|parallax
// ...] [--kernel MODEL] [--taps N] [--rank R] [--gaussians N]: one image of a mesh with one shading
// method, through the render pipeline.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "../parallax_scene.h"
#include "../pass_timings_json.h"
#include "command.h"
#include "gl_environment.h"
#include "output.h"
#include "raymarch_scene.h"
#include "texture_space_setup.h"

#include "../organ_data.h"
#include "tissue/context/headless_context.h"
#include "tissue/core/image.h"
#include "tissue/core/vec_math.h"
#include "tissue/render/renderer.h"

namespace tissue::sim_app {
namespace {

struct RenderOptions {
  std::string mesh = (dataDir() / "meshes" / "liver.obj").string();
  std::string method = "lit";
  std::string kernel = "preintegrated";
  int taps = 17;
  int rank = 1;          // separable: SVD rank or d'Eon Gaussians (components, Freude eq. 5.10)
  std::string material;  // data/materials/<name>.json; default: the mesh's stem
  std::string out;
  int width = 1024;  // pixels
  int height = 768;  // pixels
  std::string normalMap;
  std::string baseColor;
  float scale = 1.0f;  // mm per file unit
  int samples = 4;
  int gaussians = 6;                                // texture-space: profile terms
  int mapSize = 1024;                               // texture-space: T_max, texels
  bool cull = true, clip = true, depthSize = true;  // texture-space: Jimenez et al. §3, §5, §4
  int marchSamples = 50;                            // raymarch: samples per pixel
  bool adaptive = false;                            // raymarch: per-pixel sample count
  ParallaxOptions parallax;                         // --method parallax
};

// The key light sits above, right of and behind the camera, at the camera's distance.
render::Light keyLight(const render::Camera& camera) {
  const Float3 forward = camera.target - camera.eye;
  const float distance = length(forward);
  const Float3 f = normalize(forward);
  const Float3 right = normalize(cross(f, camera.up));
  const Float3 up = cross(right, f);
  render::Light light;
  light.positionMm = camera.eye + (right * 0.6f + up * 0.8f) * distance;
  return light;
}

Result<Image8> readTexture(const std::string& path, const char* what) {
  auto image = readImage(path, 4);
  if (!image) return Error{std::string(what) + " " + path + ": " + image.error().message};
  return image;
}

// --method parallax: the layered-parallax method on the mesh's own UVs (else an atlas).
int renderParallax(const RenderOptions& o, const GlobalOptions& global) {
  const char* cmd = "render";
  auto loaded = loadParallaxScene(o.mesh, o.scale, float(o.width) / float(o.height), o.samples, o.parallax);
  if (!loaded) return fail(cmd, loaded.error().message);
  ParallaxScene& p = *loaded;
  p.scene.lights = {keyLight(p.scene.camera)};
  p.scene.lights[0].castsShadows = true;
  auto first = p.renderer->renderImage(p.scene, o.width, o.height);  // allocations, shader caches
  if (!first) return fail(cmd, first.error().message);
  const double firstMs = p.renderer->lastTimings().totalCpuMs;
  auto image = p.renderer->renderImage(p.scene, o.width, o.height);
  if (!image) return fail(cmd, image.error().message);
  const render::RenderTimings t = p.renderer->lastTimings();
  if (auto w = writePng(o.out, *image); !w) return fail(cmd, w.error().message);
  const auto& s = std::get<render::ParallaxSettings>(p.scene.objects[0].method);
  nlohmann::json out;
  out["out"] = o.out;
  out["method"] = "parallax";
  out["width"] = o.width;
  out["height"] = o.height;
  out["gl_renderer"] = p.context->info().renderer;
  out["render_ms"] = t.totalCpuMs;
  out["first_frame_ms"] = firstMs;
  out["passes"] = passTimingsJson(t);
  out["layer_depth_mm"] = s.layers[0].depthMm;
  out["refractive_index"] = s.refractiveIndex;
  out["lightmap_size"] = s.lightmap.size;
  out["lightmap_reduction"] = s.lightmap.reduction;
  out["blur_radius_mm"] = s.lightmap.blurRadiusMm;
  out["blur_passes"] = s.lightmap.blurPasses;
  out["cull"] = s.lightmap.cull;
  out["clip"] = s.lightmap.clip;
  out["uvs"] =
      p.organ.atlas ? "automatic atlas (" + std::to_string(p.organ.charts) + " charts)" : "the mesh's own";
  out["textures"] = p.textured ? "data/textures/<mesh>/ (inner layer: inner_base.png)" : "defaults";
  printResult(global, out);
  return 0;
}

int run(RenderOptions o, const GlobalOptions& global) {
  const char* cmd = "render";
  // A mesh of the project's own data gets its material file's textures unless others are given
  // (the scene module's one reader; a mesh without data/materials/<stem>.json has none).
  const auto stem = std::filesystem::path(o.mesh).stem().string();
  if (const auto file = materialFileFor(o.mesh); std::filesystem::exists(file)) {
    if (auto material = readDataMaterial(file)) {
      if (o.normalMap.empty()) o.normalMap = material->textures.normalMap.string();
      if (o.baseColor.empty()) o.baseColor = material->textures.baseColor.string();
    }
  }
  if (o.width <= 0 || o.height <= 0) return fail(cmd, "--width and --height must be positive pixels");
  if (o.method == "raymarch")
    return runRayMarchRender(o.mesh, o.out, o.width, o.height, o.marchSamples, o.adaptive, global);
  if (o.method == "parallax") return renderParallax(o, global);
  if (o.method != "lit" && o.method != "separable" && o.method != "texture-space") {
    return fail(cmd, "--method " + o.method + " is not one of lit, separable, texture-space, raymarch");
  }
  render::SceneObject object;
  if (o.method != "lit") {
    if (o.material.empty()) o.material = stem;
    auto optical = loadDataMaterial(o.material);
    if (!optical) return fail(cmd, "--material " + o.material + ": " + optical.error().message);
    if (o.method == "separable") {
      auto separable = makeSeparableMaterial(*optical, o.kernel, o.taps, o.rank);
      if (!separable)
        return fail(cmd, "--kernel " + o.kernel + " --taps " + std::to_string(o.taps) + " --rank " +
                             std::to_string(o.rank) + ": " + separable.error().message);
      object.method = separable->settings;
    } else {
      auto settings = makeTextureSpaceSettings(*optical, o.gaussians);
      if (!settings)
        return fail(cmd, "--gaussians " + std::to_string(o.gaussians) + ": " + settings.error().message);
      settings->mapSize = o.mapSize;
      settings->cull = o.cull, settings->clip = o.clip, settings->depthSize = o.depthSize;
      object.method = *settings;
    }
  }
  // Step 1: the mesh, its angle-weighted normals (per geometric vertex, so seams stay smooth)
  // and UV tangent frames.
  // Texture space needs unique UVs: the mesh's own when usable, else the automatic atlas (whose
  // UVs the mesh's textures do not follow).
  auto loaded = o.method == "texture-space" ? loadTsdOrgan(o.mesh, o.scale) : loadRenderMesh(o.mesh, o.scale);
  if (!loaded) return fail(cmd, loaded.error().message);
  SurfaceMesh& m = loaded->mesh;
  std::vector<Float3>& normals = loaded->normals;
  std::vector<Float4>& tangents = loaded->tangents;
  const bool hasUvs = m.hasUvs() && !loaded->atlas;
  if (!m.hasUvs()) m.uvs.assign(m.positions.size(), Float2{});  // no UVs: shade with the vertex normals only
  // Step 2: a context, the renderer, the mesh and textures.
  auto context = createAppContext({}, false);
  if (!context) return fail(cmd, context.error().message);
  auto renderer = render::Renderer::create(
      (*context)->procAddressFunction(),
      {.shaders = shaderSettingsFromEnvironment(), .samples = o.samples, .gpuTimers = true});
  if (!renderer) return fail(cmd, renderer.error().message);
  auto meshHandle = renderer->createMesh({m.positions, normals, tangents, m.uvs, m.triangles, {}});
  if (!meshHandle) return fail(cmd, meshHandle.error().message);
  object.mesh = *meshHandle;
  for (auto [path, handle, what] : {std::tuple{o.baseColor, &object.baseColor, "--base-color"},
                                    std::tuple{o.normalMap, &object.normalMap, "--normal-map"}}) {
    if (path.empty() || !hasUvs) continue;
    auto image = readTexture(path, what);
    if (!image) return fail(cmd, image.error().message);
    auto texture = renderer->createTexture(*image);
    if (!texture) return fail(cmd, texture.error().message);
    *handle = *texture;
  }
  // Step 3: frame the bounding box, light it, render (a first frame allocates the target).
  const Bounds3 box = boundsOf(m.positions);
  const Float3 lo = box.lo, hi = box.hi;
  render::Scene scene;
  scene.camera = render::frameBoundingBox(lo, hi, static_cast<float>(o.width) / static_cast<float>(o.height));
  scene.lights = {keyLight(scene.camera)};
  scene.lights[0].castsShadows = true;  // shadows, and the separable method's transmission
  scene.objects = {object};
  auto first = renderer->renderImage(scene, o.width, o.height);
  if (!first) return fail(cmd, first.error().message);
  const double firstMs = renderer->lastTimings().totalCpuMs;
  auto image = renderer->renderImage(scene, o.width, o.height);
  if (!image) return fail(cmd, image.error().message);
  const render::RenderTimings t = renderer->lastTimings();
  // Step 4: write atomically and report.
  if (auto w = writePng(o.out, *image); !w) return fail(cmd, w.error().message);
  nlohmann::json out;
  out["out"] = o.out;
  out["width"] = o.width;
  out["height"] = o.height;
  out["gl_context"] = (*context)->info().backend;
  out["gl_renderer"] = (*context)->info().renderer;
  out["render_ms"] = t.totalCpuMs;
  out["first_frame_ms"] = firstMs;
  out["passes"] = passTimingsJson(t);
  out["upload_ms"] = t.uploadCpuMs;
  out["samples"] = o.samples;
  out["method"] = o.method;
  if (o.method == "separable") {
    out["kernel"] = o.kernel;
    out["taps"] = o.taps;
    out["rank"] = o.rank;
    out["material"] = o.material;
  }
  if (o.method == "texture-space") {
    out["gaussians"] = o.gaussians;
    out["map_size"] = o.mapSize;
    out["cull"] = o.cull, out["clip"] = o.clip, out["depth_size"] = o.depthSize;
    out["uvs"] =
        loaded->atlas ? "automatic atlas (" + std::to_string(loaded->charts) + " charts)" : "the mesh's own";
  }
  if (o.method != "lit") out["material"] = o.material;
  out["triangles"] = m.triangles.size();
  out["shading"] = hasUvs ? (o.normalMap.empty() ? "vertex normals (no --normal-map)" : "normal-mapped")
                   : loaded->atlas ? "vertex normals (automatic UV atlas; the mesh's textures ignored)"
                                   : "vertex normals (mesh has no UVs; textures ignored)";
  out["normal_map"] = hasUvs ? o.normalMap : "";
  out["base_color"] = hasUvs ? o.baseColor : "";
  printResult(global, out);
  return 0;
}

}  // namespace

void registerRenderCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto opts = std::make_shared<RenderOptions>();
  auto* cmd = app.add_subcommand("render", "render a mesh with one shading method to a PNG");
  cmd->add_option("--mesh", opts->mesh, "mesh file (OBJ, PLY, OFF, STL; default data/meshes/liver.obj)");
  cmd->add_option("--method", opts->method,
                  "shading method: lit, separable (screen-space SSS), texture-space, raymarch or parallax");
  cmd->add_option("--kernel", opts->kernel,
                  "separable kernel model: svd, preintegrated, guided, manual, deon, jimenez");
  cmd->add_option("--taps", opts->taps, "separable kernel taps per 1D pass (odd, default 17)");
  cmd->add_option("--rank", opts->rank,
                  "separable kernel components: svd rank or deon Gaussian count, 1..8 (default 1)");
  cmd->add_option("--material", opts->material,
                  "data/materials/<NAME>.json for separable and texture-space (default: the mesh's name)");
  cmd->add_option("--out", opts->out, "output PNG (written atomically)")->required();
  cmd->add_option("--width", opts->width, "image width, pixels (default 1024)");
  cmd->add_option("--height", opts->height, "image height, pixels (default 768)");
  cmd->add_option("--normal-map", opts->normalMap, "tangent-space normal map PNG (needs UVs)");
  cmd->add_option("--base-color", opts->baseColor, "base colour PNG, sRGB (needs UVs)");
  cmd->add_option("--scale", opts->scale, "mm per file unit (default 1)");
  cmd->add_option("--samples", opts->samples, "MSAA samples (default 4; 0 = off)");
  cmd->add_option("--gaussians", opts->gaussians,
                  "texture-space: Gaussians fitted to the material's profile, 1..8 (default 6)");
  cmd->add_option("--map-size", opts->mapSize, "texture-space: T_max, irradiance map texels (default 1024)");
  cmd->add_flag(
      "--no-cull", [opts](std::int64_t) { opts->cull = opts->parallax.settings.lightmap.cull = false; },
      "texture-space and parallax: no culled map");
  cmd->add_flag(
      "--no-clip", [opts](std::int64_t) { opts->clip = opts->parallax.settings.lightmap.clip = false; },
      "texture-space and parallax: no clipped map");
  cmd->add_flag(
      "--no-depth-size", [opts](std::int64_t) { opts->depthSize = false; },
      "texture-space: no depth-based map size");
  cmd->add_option("--layer-depth", opts->parallax.layerDepthMm,
                  "parallax: inner layer depth, mm (default 1.5)");
  cmd->add_option("--refractive-index", opts->parallax.settings.refractiveIndex,
                  "parallax: relative refractive index n_inside / n_outside (default 1.4; 1 = Oat 2006)");
  cmd->add_option("--blur-radius", opts->parallax.settings.lightmap.blurRadiusMm,
                  "parallax: lightmap Poisson-disc radius of all passes, mm (default 4)");
  cmd->add_option("--blur-passes", opts->parallax.settings.lightmap.blurPasses,
                  "parallax: lightmap blur passes (default 3)");
  cmd->add_option("--lightmap-size", opts->parallax.settings.lightmap.size,
                  "parallax: irradiance pass texels a side (default 1024)");
  cmd->add_option("--lightmap-reduction", opts->parallax.settings.lightmap.reduction,
                  "parallax: the blurred lightmap is size / reduction texels (1, 2, 4, 8; default 4)");
  cmd->add_option("--march-samples", opts->marchSamples, "raymarch: samples per pixel (default 50)");
  cmd->add_flag("--adaptive", opts->adaptive, "raymarch: choose the sample count per pixel");
  cmd->callback([opts, &global, &exitCode] { exitCode = run(*opts, global); });
}

}  // namespace tissue::sim_app
