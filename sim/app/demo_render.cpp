#include "demo_render.h"
#include "gl_environment.h"

#include <algorithm>
#include <optional>

#include "organ_data.h"
#include "output.h"
#include "pass_timings_json.h"
#include "tissue/context/headless_context.h"
#include "tissue/core/image.h"
#include "tissue/core/vec_math.h"
#include "tissue/render/renderer.h"
#include "tissue/scene/organ_methods.h"
#include "tissue/studies/sss_bench.h"

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
  scene::OrganTextures textures, loopTextures;  // the organ's, on each renderer
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

Result<void> DemoRenderer::prepare(const mesh::DeformableSurface& surface, const scene::OrganAssets& organ) {
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
    auto textures = scene::uploadOrganTextures(*s.renderer, organ);
    if (!textures) return *(s.setupError = textures.error());
    s.textures = *textures;
    auto mesh = s.renderer->createMesh(
        {surface.positions(), surface.normals(), surface.tangents(), surface.uvs(), surface.triangles(), {}});
    if (!mesh) return *(s.setupError = mesh.error());
    s.scene.objects = {scene::organObject(*mesh, s.textures, render::LitSettings{})};
    const Bounds3 box = boundsOf(surface.geometricRestPositions());
    const Float3 lo = box.lo, hi = box.hi;
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

Result<scene::RenderRequest> DemoRenderer::attachLoop(scene::OrganLoop& loop, const scene::OrganAssets& organ,
                                                      int width, int height, Image8* image) {
  if (auto ok = prepare(loop.surface(), organ); !ok) return ok.error();
  auto& s = *m_impl;
  render::RendererSettings settings;
  settings.samples = 0;
  settings.gpuTimers = false;
  settings.shaders = shaderSettingsFromEnvironment();
  auto r = render::Renderer::create(s.context->procAddressFunction(), settings);
  if (!r) return r.error();
  s.loopRenderer.emplace(std::move(*r));
  auto textures = scene::uploadOrganTextures(*s.loopRenderer, organ);
  if (!textures) return textures.error();
  s.loopTextures = *textures;
  s.loopScene = s.scene;
  auto& object = s.loopScene->objects[0];
  object.baseColor = s.loopTextures.baseColor;
  object.normalMap = s.loopTextures.normalMap;
  auto handle = loop.attach(*s.loopRenderer);
  if (!handle) return handle.error();
  object.mesh = *handle;
  object.method = render::LitSettings{};
  if (auto tool = loop.instrumentObject()) s.loopScene->objects.push_back(*tool);
  scene::RenderRequest request;
  request.scene = &*s.loopScene;
  request.width = width;
  request.height = height;
  request.image = image;
  return request;
}

Result<void> DemoRenderer::render(const mesh::DeformableSurface& surface, const scene::OrganAssets& organ,
                                  const std::filesystem::path& png) {
  auto& s = *m_impl;
  if (auto ok = prepare(surface, organ); !ok) return ok.error();
  // Upload: the whole mesh once (above), then only what deforms.
  auto up = s.renderer->updateMesh(s.scene.objects[0].mesh,
                                   {0, surface.positions(), surface.normals(), surface.tangents(), {}});
  if (!up) return up.error();
  s.scene.objects[0].method = render::LitSettings{};
  auto image = s.renderer->renderImage(s.scene, s.width, s.height);
  if (!image) return image.error();
  return writePng(png, *image);
}

nlohmann::json DemoRenderer::renderSubsurface(const mesh::DeformableSurface& surface,
                                              const scene::OrganAssets& organ,
                                              const std::filesystem::path& png, bool textureSpace) {
  auto& s = *m_impl;
  auto fail = [](const std::string& why) { return nlohmann::json{{"skipped", why}}; };
  // Step 1: both methods' settings from the material's first layer (its dipole profile), as
  // every app gets them (scene::organMethod, the main job's choices); the kernel's truth, the
  // reference's profile, from the same model.
  if (auto ok = prepare(surface, organ); !ok) return fail(ok.error().message);
  const scene::MethodChoices choices;
  auto separable = scene::organMethod(render::ShadingMethod::Separable, organ, s.textures, choices);
  if (!separable) return fail(separable.error().message);
  auto truth = makeSeparableMaterial(scene::opticalMaterial(organ.material), choices.kernel, choices.taps,
                                     choices.rank);
  if (!truth) return fail(truth.error().message);
  std::optional<render::MethodSettings> tsd;
  if (textureSpace) {
    auto settings = scene::organMethod(render::ShadingMethod::TextureSpace, organ, s.textures, choices);
    if (!settings) return fail(settings.error().message);
    tsd = std::move(*settings);
  }
  // Step 2: the organ as it is now, separable, lit by a shadow-casting lamp (shadows and
  // transmission); its pre-blur diffuse is the reference's input for both methods.
  if (auto lit = render(surface, organ, png); !lit) return fail(lit.error().message);
  s.scene.objects[0].method = *separable;
  s.scene.lights[0].castsShadows = true;
  auto image = s.renderer->renderImage(s.scene, s.width, s.height);
  auto diffuse = s.renderer->readFrame(render::FrameView::Diffuse);
  auto position = s.renderer->readFrame(render::FrameView::Position);
  // Step 3: the same object switched to texture-space diffusion at run time.
  if (image && tsd) {
    s.scene.objects[0].method = *tsd;
    image = s.renderer->renderImage(s.scene, s.width, s.height);
  }
  s.scene.lights[0].castsShadows = false;
  s.scene.objects[0].method = render::LitSettings{};
  if (!image) return fail(image.error().message);
  if (auto w = writePng(png, *image); !w) return fail(w.error().message);
  nlohmann::json j{{"image", png.filename().string()},
                   {"material", organ.material.name},
                   {"passes", passTimingsJson(s.renderer->lastTimings())},
                   {"total_cpu_ms", s.renderer->lastTimings().totalCpuMs}};
  if (tsd)
    j["gaussians"] = std::get<render::TextureSpaceSettings>(*tsd).gaussians.size();
  else
    j["kernel"] = truth->kernelName;
  // Step 4: the subsurface diffuse against the CPU reference on this frame.
  // The subsurface diffuse against the exact convolution of the frame's pre-blur diffuse:
  // texture-space pixels hold their diffused radiance in the Diffuse view, so both methods are
  // measured against the pre-blur diffuse and position of the frame rendered separably.
  if (diffuse && position) {
    if (auto e = studies::lastFrameReferenceError(*s.renderer, *diffuse, *position, truth->truth)) {
      j["reference_ms"] = e->referenceMs;
      j["image_rms"] = e->imageRms;
      j["relative_rms"] = e->relativeRms;
    }
  }
  return j;
}

nlohmann::json DemoRenderer::renderParallax(const mesh::DeformableSurface& surface,
                                            const scene::OrganAssets& organ,
                                            const std::filesystem::path& png) {
  auto& s = *m_impl;
  auto fail = [](const std::string& why) { return nlohmann::json{{"skipped", why}}; };
  // Step 1: the organ as it is now (uploads the deformation), then the parallax settings of its
  // inner layer (uploaded with the organ's textures).
  if (auto lit = render(surface, organ, png); !lit) return fail(lit.error().message);
  auto method = scene::organMethod(render::ShadingMethod::Parallax, organ, s.textures);
  if (!method) return fail(method.error().message);
  const auto& settings = std::get<render::ParallaxSettings>(*method);
  // Step 2: the same object switched to parallax for one frame, then back.
  s.scene.objects[0].method = *method;
  auto image = s.renderer->renderImage(s.scene, s.width, s.height);
  s.scene.objects[0].method = render::LitSettings{};
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
