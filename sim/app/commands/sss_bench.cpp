// tissue-sim sss-bench [--mesh FILE] [--width W --height H] [--frames N] [--samples S] --json: every
// subsurface-scattering method and setting on one frame of the organ, with its time and its
// image RMS against the CPU reference (the exact screen-space convolution with the material's
// dipole profile, tissue::reference). Methods add rows through kMethods below.
#include <filesystem>

#include "../organ_data.h"
#include "../sss_bench.h"
#include "command.h"
#include "gl_environment.h"
#include "output.h"
#include "tissue/context/headless_context.h"
#include "tissue/core/vec_math.h"
#include "tissue/mesh/deformable_surface.h"
#include "tissue/mesh/load_mesh.h"
#include "tissue/mesh/tangent_frames.h"
#include "tissue/mesh/vertex_normals.h"

namespace tissue::sim_app {
namespace {

// Every method of the bench, in the order of the results list.
const SssBenchMethod kMethods[] = {
    {"separable", separableBenchRows},
    {"texture-space", textureSpaceBenchRows},
};

struct BenchOptions {
  std::string mesh = (dataDir() / "meshes" / "liver.obj").string();
  int width = 320;   // pixels
  int height = 240;  // pixels
  int frames = 5;
  int samples = 0;  // MSAA
};

// The organ with normals, tangents and its textures, uploaded as object 1 of the scene.
Result<void> uploadOrgan(SssBenchContext& ctx, const std::string& path) {
  auto loaded = mesh::loadMesh(path, {.requireUvs = true, .scaleToMm = 1.0f});
  if (!loaded) return loaded.error();
  SurfaceMesh& m = *loaded;
  std::vector<Float3> geoNormals(m.geometricVertexCount), normals;
  mesh::computeVertexNormals(mesh::geometricPositionsOf(m), mesh::geometricTrianglesOf(m), geoNormals);
  gatherToRenderVertices(m, geoNormals, normals);
  std::vector<Float4> tangents(m.positions.size());
  mesh::computeTangentFrames(m.positions, m.uvs, m.triangles, normals, tangents, m.geometricIndex);
  auto handle = ctx.renderer->createMesh({m.positions, normals, tangents, m.uvs, m.triangles, {}});
  if (!handle) return handle.error();
  render::SceneObject organ;
  organ.mesh = *handle;
  const auto stem = std::filesystem::path(path).stem().string();
  for (auto [name, slot] :
       {std::pair{"base_color", &organ.baseColor}, std::pair{"normal_map", &organ.normalMap}}) {
    const auto file = findDataTexture(stem, name);
    if (file.empty()) continue;
    auto image = readImage(file, 4);
    if (!image) return image.error();
    auto texture = ctx.renderer->createTexture(*image);
    if (!texture) return texture.error();
    *slot = *texture;
  }
  const Bounds3 box = boundsOf(m.positions);
  const Float3 lo = box.lo, hi = box.hi;
  ctx.scene.camera = render::frameBoundingBox(lo, hi, float(ctx.width) / float(ctx.height));
  const Float3 c{(lo.x + hi.x) / 2, (lo.y + hi.y) / 2, (lo.z + hi.z) / 2};
  ctx.scene.lights[0].positionMm = {c.x + 150.0f, c.y + 200.0f, hi.z + 300.0f};
  ctx.scene.lights[0].castsShadows = true;
  ctx.scene.objects = {organ};
  return {};
}

int run(const BenchOptions& o, const GlobalOptions& global) {
  const char* cmd = "sss-bench";
  if (o.width <= 0 || o.height <= 0 || o.frames <= 0)
    return fail(cmd, "--width, --height and --frames must be positive");
  SssBenchContext ctx;
  ctx.width = o.width;
  ctx.height = o.height;
  ctx.frames = o.frames;
  const auto stem = std::filesystem::path(o.mesh).stem().string();
  auto material = loadDataMaterial(stem);
  if (!material) return fail(cmd, "material for " + o.mesh + ": " + material.error().message);
  ctx.material = *material;
  auto truth = makeSeparableMaterial(ctx.material, "preintegrated", 17);
  if (!truth) return fail(cmd, truth.error().message);
  ctx.profiles = {reference::RadialProfile{}, truth->truth};
  auto context = createAppContext({}, false);
  if (!context) return fail(cmd, context.error().message);
  render::RendererSettings settings;
  settings.samples = o.samples;
  settings.shaders = shaderSettingsFromEnvironment();
  auto renderer = render::Renderer::create((*context)->procAddressFunction(), settings);
  if (!renderer) return fail(cmd, renderer.error().message);
  ctx.renderer = &*renderer;
  if (auto r = uploadOrgan(ctx, o.mesh); !r) return fail(cmd, o.mesh + ": " + r.error().message);
  nlohmann::json results = nlohmann::json::array(), skipped = nlohmann::json::array();
  for (const SssBenchMethod& method : kMethods) {
    auto rows = method.rows(ctx, skipped);
    if (!rows) return fail(cmd, std::string(method.name) + ": " + rows.error().message);
    for (const SssBenchRow& r : *rows) {
      results.push_back({{"method", r.method},
                         {"setting", r.setting},
                         {"ms", r.ms},
                         {"method_ms", r.methodMs},
                         {"image_rms", r.imageRms},
                         {"relative_rms", r.relativeRms}});
    }
  }
  nlohmann::json out;
  out["mesh"] = o.mesh;
  out["material"] = ctx.material.name;
  out["width"] = o.width;
  out["height"] = o.height;
  out["frames"] = o.frames;
  out["samples"] = o.samples;
  out["gl_renderer"] = (*context)->info().renderer;
  out["reference"] = "exact screen-space convolution with the normalised dipole profile (tissue::reference)";
  out["results"] = results;
  out["skipped"] = skipped;
  printResult(global, out);
  return 0;
}

}  // namespace

void registerSssBenchCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto opts = std::make_shared<BenchOptions>();
  auto* cmd = app.add_subcommand("sss-bench",
                                 "time SSS methods and measure their image RMS against the CPU reference");
  cmd->add_option("--mesh", opts->mesh, "organ mesh with UVs (default data/meshes/liver.obj)");
  cmd->add_option("--width", opts->width, "image width, pixels (default 320)");
  cmd->add_option("--height", opts->height, "image height, pixels (default 240)");
  cmd->add_option("--frames", opts->frames, "timed frames per setting (default 5)");
  cmd->add_option("--samples", opts->samples, "MSAA samples (default 0 = off)");
  cmd->callback([opts, &global, &exitCode] { exitCode = run(*opts, global); });
}

}  // namespace tissue::sim_app
