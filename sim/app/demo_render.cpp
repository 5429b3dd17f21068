#include "demo_render.h"
#include "gl_environment.h"

#include <algorithm>
#include <limits>
#include <optional>

#include "output.h"
#include "pass_timings_json.h"
#include "sss_bench.h"
#include "sss_material.h"
#include "tissue/context/headless_context.h"
#include "tissue/core/image.h"
#include "tissue/core/stopwatch.h"
#include "tissue/mesh/uv_atlas.h"
#include "tissue/reference/screen_convolution.h"
#include "tissue/render/renderer.h"

namespace tissue::sim_app {

struct DemoRenderer::Impl {
  int width, height;
  std::unique_ptr<context::GlContext> context;
  std::optional<render::Renderer> renderer;
  std::optional<Error> setupError;
  render::Scene scene;  // one object: the organ
  // The same, drawing the frame loop's mesh. Optional: a second default-constructed Scene member
  // trips GCC 12's -Wmaybe-uninitialized (a false positive in its initializer-list copy).
  std::optional<render::Scene> loopScene;
  // The loop's renderer on the same context: no MSAA and no GPU timers, so that a frame costs
  // what a trainee's frame would (4x MSAA of three float targets is llvmpipe's heaviest pass).
  std::optional<render::Renderer> loopRenderer;
};

DemoRenderer::DemoRenderer(int width, int height) : m_impl(std::make_unique<Impl>()) {
  m_impl->width = width;
  m_impl->height = height;
}

DemoRenderer::~DemoRenderer() {
  if (m_impl->context) (void)m_impl->context->makeCurrent();  // GL objects die with their context current
  m_impl->loopRenderer.reset();
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

Result<void> DemoRenderer::prepare(const mesh::DeformableSurface& surface, const LayeredMaterial& material) {
  auto& s = *m_impl;
  if (s.setupError) return *s.setupError;
  // Setup on first use: context, renderer, textures, a camera framing the rest shape.
  if (!s.renderer) {
    context::ContextRequest request;
    request.width = request.height = 16;  // the renderer draws into its own framebuffer
    auto ctx = createAppContext(request);
    if (!ctx) return *(s.setupError = ctx.error());
    s.context = std::move(*ctx);
    render::RendererSettings settings;
    settings.samples = 4;
    settings.shaders = shaderSettingsFromEnvironment();
    auto r = render::Renderer::create(s.context->procAddressFunction(), settings);
    if (!r) return *(s.setupError = r.error());
    s.renderer.emplace(std::move(*r));
    const auto stem = material.name;
    render::SceneObject organ;
    for (const auto& [name, slot] :
         {std::pair{"base_color", &organ.baseColor}, std::pair{"normal_map", &organ.normalMap}}) {
      auto tex = loadTexture(stem, name);
      if (!tex) return *(s.setupError = tex.error());
      auto handle = s.renderer->createTexture(*tex);
      if (!handle) return *(s.setupError = handle.error());
      *slot = *handle;
    }
    auto mesh = s.renderer->createMesh(
        {surface.positions(), surface.normals(), surface.tangents(), surface.uvs(), surface.triangles(), {}});
    if (!mesh) return *(s.setupError = mesh.error());
    organ.mesh = *mesh;
    s.scene.objects = {organ};
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
  return s.context->makeCurrent();
}

Result<void> DemoRenderer::makeCurrent() {
  if (!m_impl->context) return Error{"demo: the renderer is not set up"};
  return m_impl->context->makeCurrent();
}

Result<scene::RenderRequest> DemoRenderer::attachLoop(scene::OrganLoop& loop, const LayeredMaterial& material,
                                                      int width, int height, Image8* image) {
  if (auto ok = prepare(loop.surface(), material); !ok) return ok.error();
  auto& s = *m_impl;
  render::RendererSettings settings;
  settings.samples = 0;
  settings.gpuTimers = false;
  settings.shaders = shaderSettingsFromEnvironment();
  auto r = render::Renderer::create(s.context->procAddressFunction(), settings);
  if (!r) return r.error();
  s.loopRenderer.emplace(std::move(*r));
  s.loopScene = s.scene;
  auto& organ = s.loopScene->objects[0];
  for (const auto& [name, slot] :
       {std::pair{"base_color", &organ.baseColor}, std::pair{"normal_map", &organ.normalMap}}) {
    auto tex = loadTexture(material.name, name);
    if (!tex) return tex.error();
    auto handle = s.loopRenderer->createTexture(*tex);
    if (!handle) return handle.error();
    *slot = *handle;
  }
  auto handle = loop.attach(*s.loopRenderer);
  if (!handle) return handle.error();
  organ.mesh = *handle;
  organ.method = render::LitSettings{};
  if (auto tool = loop.instrumentObject()) s.loopScene->objects.push_back(*tool);
  scene::RenderRequest request;
  request.scene = &*s.loopScene;
  request.width = width;
  request.height = height;
  request.image = image;
  return request;
}

Result<void> DemoRenderer::render(const mesh::DeformableSurface& surface, const LayeredMaterial& material,
                                  const std::filesystem::path& png) {
  auto& s = *m_impl;
  if (auto ok = prepare(surface, material); !ok) return ok.error();
  // Upload: the whole mesh once (above), then only what deforms.
  auto up = s.renderer->updateMesh(s.scene.objects[0].mesh,
                                   {0, surface.positions(), surface.normals(), surface.tangents(), {}});
  if (!up) return up.error();
  s.scene.objects[0].method = render::LitSettings{};
  auto image = s.renderer->renderImage(s.scene, s.width, s.height);
  if (!image) return image.error();
  return writePng(png, *image);
}

namespace {

/// The frame's subsurface diffuse (after the blur or the texture-space diffusion) against the
/// exact convolution of its pre-blur diffuse with `truth` (tissue::reference), into `j`.
/// Texture-space pixels hold their diffused radiance in the Diffuse view, so the caller passes
/// the pre-blur `diffuse` and `position` of the same frame rendered separably.
void addReferenceError(render::Renderer& renderer, const render::FloatImage& diffuse,
                       const render::FloatImage& position, const reference::RadialProfile& truth,
                       nlohmann::json& j) {
  auto blurred = renderer.readFrame(render::FrameView::BlurredDiffuse);
  auto radiance = renderer.readFrame(render::FrameView::Radiance);
  if (!blurred || !radiance) return;
  std::vector<Float4> pre = diffuse.pixels;
  dropPartialCoverage(pre, *radiance);  // MSAA silhouettes are not surface points
  const reference::ScreenBuffers frame{diffuse.width, diffuse.height, pre, position.pixels};
  const std::vector<reference::RadialProfile> profiles{{}, truth};
  Stopwatch watch;
  if (auto exact = reference::convolveScreen(frame, profiles); exact) {
    j["reference_ms"] = watch.elapsedMs();
    const auto e = reference::compareWithReference(frame, blurred->pixels, *exact, profiles);
    j["image_rms"] = e.rms;
    j["relative_rms"] = e.relativeRms;
  }
}

}  // namespace

nlohmann::json DemoRenderer::renderSubsurface(const mesh::DeformableSurface& surface,
                                              const LayeredMaterial& material,
                                              const std::filesystem::path& png, bool textureSpace) {
  auto& s = *m_impl;
  auto fail = [](const std::string& why) { return nlohmann::json{{"skipped", why}}; };
  // Step 1: both methods' settings from the material's first layer (its dipole profile).
  auto optical = loadDataMaterial(material.name);
  if (!optical) return fail(optical.error().message);
  auto separable = makeSeparableMaterial(*optical, "preintegrated", 17);
  if (!separable) return fail(separable.error().message);
  auto tsd = makeTextureSpaceSettings(*optical, 6);
  if (!tsd) return fail(tsd.error().message);
  if (textureSpace && !mesh::hasUsableUvs(surface.uvs(), surface.triangles(), surface.positions().size()))
    return fail(
        "texture-space diffusion needs unique UVs, and the organ's UVs overlap (mesh::computeUvAtlas makes "
        "unique ones)");
  // Step 2: the organ as it is now, separable, lit by a shadow-casting lamp (shadows and
  // transmission); its pre-blur diffuse is the reference's input for both methods.
  if (auto lit = render(surface, material, png); !lit) return fail(lit.error().message);
  s.scene.objects[0].method = separable->settings;
  s.scene.lights[0].castsShadows = true;
  auto image = s.renderer->renderImage(s.scene, s.width, s.height);
  auto diffuse = s.renderer->readFrame(render::FrameView::Diffuse);
  auto position = s.renderer->readFrame(render::FrameView::Position);
  // Step 3: the same object switched to texture-space diffusion at run time.
  if (image && textureSpace) {
    s.scene.objects[0].method = *tsd;
    image = s.renderer->renderImage(s.scene, s.width, s.height);
  }
  s.scene.lights[0].castsShadows = false;
  s.scene.objects[0].method = render::LitSettings{};
  if (!image) return fail(image.error().message);
  if (auto w = writePng(png, *image); !w) return fail(w.error().message);
  nlohmann::json j{{"image", png.filename().string()},
                   {"material", optical->name},
                   {"passes", passTimingsJson(s.renderer->lastTimings())},
                   {"total_cpu_ms", s.renderer->lastTimings().totalCpuMs}};
  if (textureSpace)
    j["gaussians"] = tsd->gaussians.size();
  else
    j["kernel"] = separable->kernelName;
  // Step 4: the subsurface diffuse against the CPU reference on this frame.
  if (diffuse && position) addReferenceError(*s.renderer, *diffuse, *position, separable->truth, j);
  return j;
}

nlohmann::json DemoRenderer::renderParallax(const mesh::DeformableSurface& surface,
                                            const LayeredMaterial& material,
                                            const std::filesystem::path& png) {
  auto& s = *m_impl;
  auto fail = [](const std::string& why) { return nlohmann::json{{"skipped", why}}; };
  // Step 1: the organ as it is now (uploads the deformation), then its inner layer's textures.
  if (auto lit = render(surface, material, png); !lit) return fail(lit.error().message);
  render::ParallaxSettings settings;
  settings.layers = {render::ParallaxLayer{{}, 1.5f, 1.0f}};
  for (auto [name, handle] :
       {std::pair{"opacity", &settings.opacityMap}, std::pair{"inner_base", &settings.layers[0].base}}) {
    auto tex = loadTexture(material.name, name);
    if (!tex) return fail(tex.error().message);
    auto texture = s.renderer->createTexture(*tex);
    if (!texture) return fail(texture.error().message);
    *handle = *texture;
  }
  // Step 2: the same object switched to parallax for one frame, then back (the textures go).
  s.scene.objects[0].method = settings;
  auto image = s.renderer->renderImage(s.scene, s.width, s.height);
  s.scene.objects[0].method = render::LitSettings{};
  s.renderer->destroyTexture(settings.opacityMap);
  s.renderer->destroyTexture(settings.layers[0].base);
  if (!image) return fail(image.error().message);
  if (auto w = writePng(png, *image); !w) return fail(w.error().message);
  return {{"image", png.filename().string()},
          {"layer_depth_mm", settings.layers[0].depthMm},
          {"refractive_index", settings.refractiveIndex},
          {"passes", passTimingsJson(s.renderer->lastTimings())},
          {"total_cpu_ms", s.renderer->lastTimings().totalCpuMs}};
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
