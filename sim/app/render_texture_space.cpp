// tissue-sim render --method texture-space: the standalone texture-space renderer on one mesh.
#include "render_texture_space.h"

#include "output.h"
#include "texture_space_setup.h"
#include "tissue/context/headless_context.h"
#include "tissue/core/stopwatch.h"

namespace tissue::sim_app {

int renderTextureSpace(const TsdRenderOptions& o, const GlobalOptions& global) {
  const char* cmd = "render";
  auto organ = loadTsdOrgan(o.mesh, o.scale);
  if (!organ) return fail(cmd, organ.error().message);
  auto gaussians = skinGaussians(o.gaussians);
  if (!gaussians) return fail(cmd, gaussians.error().message);
  auto context = context::createHeadlessContext({}, {.backend = "", .log = false});
  if (!context) return fail(cmd, context.error().message);
  auto renderer = render::TextureSpaceRenderer::create((*context)->procAddressFunction(),
                                                       {.shaders = {}, .maxMapSize = o.mapSize});
  if (!renderer) return fail(cmd, renderer.error().message);
  if (auto r = renderer->setMesh(organ->arrays(), organ->uvDensity * float(o.mapSize)); !r)
    return fail(cmd, r.error().message);
  if (!o.baseColor.empty() && !organ->atlas) {
    auto image = readImage(o.baseColor, 4);
    if (!image) return fail(cmd, "--base-color " + o.baseColor.string() + ": " + image.error().message);
    if (auto r = renderer->setBaseColor(*image); !r) return fail(cmd, r.error().message);
  }
  render::Scene scene;
  scene.camera = render::frameBoundingBox(organ->lo, organ->hi, float(o.width) / float(o.height));
  const Float3 e = scene.camera.eye;
  scene.lights[0].positionMm = {e.x + 0.5f * (organ->hi.x - organ->lo.x), e.y + (organ->hi.y - organ->lo.y),
                                e.z};
  render::TsdSettings s;
  s.gaussians = *gaussians;
  s.cull = o.cull, s.clip = o.clip, s.depthSize = o.depthSize;
  auto first = renderer->renderImage(scene, o.width, o.height, s);  // allocations, shader caches
  if (!first) return fail(cmd, first.error().message);
  Stopwatch watch;
  auto image = renderer->renderImage(scene, o.width, o.height, s);
  if (!image) return fail(cmd, image.error().message);
  const double ms = watch.elapsedMs();
  if (auto w = writePng(o.out, *image); !w) return fail(cmd, w.error().message);
  nlohmann::json out;
  out["out"] = o.out.string();
  out["method"] = "texture-space";
  out["width"] = o.width;
  out["height"] = o.height;
  out["render_ms"] = ms;
  out["gaussians"] = o.gaussians;
  out["map_size"] = o.mapSize;
  out["cull"] = o.cull;
  out["clip"] = o.clip;
  out["depth_size"] = o.depthSize;
  out["uvs"] =
      organ->atlas ? "automatic atlas (" + std::to_string(organ->charts) + " charts)" : "the mesh's own";
  out["gl_renderer"] = (*context)->info().renderer;
  printResult(global, out);
  return 0;
}

}  // namespace tissue::sim_app
