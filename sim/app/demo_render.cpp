#include "demo_render.h"

#include <algorithm>
#include <limits>
#include <optional>

#include "output.h"
#include "pass_timings_json.h"
#include "tissue/context/headless_context.h"
#include "tissue/core/image.h"
#include "tissue/render/renderer.h"

namespace tissue::sim_app {

struct DemoRenderer::Impl {
  int width, height;
  std::unique_ptr<context::GlContext> context;
  std::optional<render::Renderer> renderer;
  std::optional<Error> setupError;
  render::Scene scene;
  bool uploaded = false;
};

DemoRenderer::DemoRenderer(int width, int height) : m_impl(std::make_unique<Impl>()) {
  m_impl->width = width;
  m_impl->height = height;
}

DemoRenderer::~DemoRenderer() {
  if (m_impl->context) (void)m_impl->context->makeCurrent();  // GL objects die with their context current
  m_impl->renderer.reset();
}

namespace {

/// The texture `name` of mesh `stem`: the build-time 1024 version, else the committed small one.
Result<Image8> loadTexture(const std::string& stem, const std::string& name) {
  if (const auto path = findDataTexture(stem, name); !path.empty()) return readImage(path, 4);
  return Error{"no texture '" + name + ".png' for mesh '" + stem + "' in " +
               (generatedDataDir() / "textures").string() + " or " + (dataDir() / "textures").string() +
               "; build the tissue_data target"};
}

}  // namespace

Result<void> DemoRenderer::render(const mesh::DeformableSurface& surface, const LayeredMaterial& material,
                                  const std::filesystem::path& png) {
  auto& s = *m_impl;
  if (s.setupError) return *s.setupError;
  // Setup on first use: context, renderer, textures, a camera framing the rest shape.
  if (!s.renderer) {
    context::ContextRequest request;
    request.width = request.height = 16;  // the renderer draws into its own framebuffer
    auto ctx = context::createHeadlessContext(request);
    if (!ctx) return *(s.setupError = ctx.error());
    s.context = std::move(*ctx);
    render::RendererSettings settings;
    settings.samples = 4;
    auto r = render::Renderer::create(s.context->procAddressFunction(), settings);
    if (!r) return *(s.setupError = r.error());
    s.renderer.emplace(std::move(*r));
    const auto stem = material.name;
    for (const auto& [name, normal] : {std::pair{"base_color", false}, std::pair{"normal_map", true}}) {
      auto tex = loadTexture(stem, name);
      if (!tex) return *(s.setupError = tex.error());
      auto set = normal ? s.renderer->setNormalMap(*tex) : s.renderer->setBaseColor(*tex);
      if (!set) return *(s.setupError = set.error());
    }
    Float3 lo{std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
              std::numeric_limits<float>::max()};
    Float3 hi{-lo.x, -lo.y, -lo.z};
    for (const auto& p : surface.geometricRestPositions()) {
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    s.scene.camera = render::frameBoundingBox(lo, hi, float(s.width) / float(s.height));
    const Float3 c{(lo.x + hi.x) / 2, (lo.y + hi.y) / 2, (lo.z + hi.z) / 2};
    s.scene.lights[0].positionMm = {c.x + 150.0f, c.y + 200.0f, hi.z + 300.0f};
  }
  if (auto ok = s.context->makeCurrent(); !ok) return ok.error();
  // Upload: the whole mesh once, then only what deforms.
  auto up = s.uploaded ? s.renderer->updateMesh(surface.positions(), surface.normals(), surface.tangents())
                       : s.renderer->setMesh({surface.positions(),
                                              surface.normals(),
                                              surface.tangents(),
                                              surface.uvs(),
                                              surface.triangles(),
                                              {}});
  if (!up) return up.error();
  s.uploaded = true;
  auto image = s.renderer->renderImage(s.scene, s.width, s.height);
  if (!image) return image.error();
  return writePng(png, *image);
}

nlohmann::json DemoRenderer::info() const {
  nlohmann::json j;
  if (!m_impl->context) return j;
  const auto& i = m_impl->context->info();
  j["gl_context"] = i.backend;
  j["gl_platform"] = i.platform;
  j["gl_vendor"] = i.vendor;
  j["gl_renderer"] = i.renderer;
  j["gl_version"] = i.version;
  if (m_impl->renderer) {
    const auto& t = m_impl->renderer->lastTimings();
    j["last_frame_ms"] = {{"upload_cpu", t.uploadCpuMs}, {"total_cpu", t.totalCpuMs}};
    j["last_frame_passes"] = passTimingsJson(t);
  }
  return j;
}

}  // namespace tissue::sim_app
