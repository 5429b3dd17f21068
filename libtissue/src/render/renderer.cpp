// The renderer: creation, GPU resources by handle, the single-mesh API, and the two ways to
// render a frame (offscreen and read back, or into a host framebuffer). The frame itself is
// in frame.cpp.
#include "tissue/render/renderer.h"

#include "renderer_impl.h"
#include "state_guard.h"
#include "textures.h"
#include "tissue/core/stopwatch.h"

namespace tissue::render {
namespace {

// Tissue-like default base colour (sRGB).
constexpr std::uint8_t kDefaultBase[3] = {196, 112, 104};

template <class M>
Result<void> createMethod(M& method, const gl::GlApi& g, const gl::ShaderLibrary& library) {
  auto m = M::create(g, library);
  if (!m) return m.error();
  method = std::move(*m);
  return {};
}

}  // namespace

const PassTiming* RenderTimings::find(const std::string& name) const {
  for (const PassTiming& p : passes)
    if (p.name == name) return &p;
  return nullptr;
}

Renderer::Renderer(std::unique_ptr<Impl> impl) : m_impl(std::move(impl)) {}
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;
Renderer::~Renderer() = default;

Result<Renderer> Renderer::create(const gl::GetProcAddressFn& getProcAddress,
                                  const RendererSettings& settings) {
  auto api = gl::loadGl(getProcAddress);
  if (!api) return Error{"renderer: " + api.error().message};
  auto impl = std::make_unique<Impl>();
  impl->api = std::move(*api);
  impl->settings = settings;
  const gl::GlApi& g = impl->gl();
  StateGuard guard(g);
  // Step 1: every method's programs, the shadow maps and the post passes.
  const gl::ShaderLibrary library(settings.shaders);
  Impl& s = *impl;
  for (auto r : {createMethod(s.lit, g, library), createMethod(s.separable, g, library),
                 createMethod(s.textureSpace, g, library), createMethod(s.rayMarch, g, library),
                 createMethod(s.parallax, g, library), createMethod(s.post, g, library),
                 createMethod(s.hostDepth, g, library)}) {
    if (!r) return r.error();
  }
  auto shadows = ShadowMaps::create(g, library, settings.shadowMapSize);
  if (!shadows) return shadows.error();
  s.shadows = std::move(*shadows);
  // Step 2: the default texture and an empty vertex array for full-screen passes.
  g.ActiveTexture(GL_TEXTURE0);
  if (auto r = uploadSolidTexture(g, s.defaultBaseColor, kDefaultBase[0], kDefaultBase[1], kDefaultBase[2]);
      !r) {
    return r.error();
  }
  s.emptyVertexArray = gl::VertexArray::create(g);
  if (auto r = gl::checkGlError(g, "renderer: create"); !r) return r.error();
  return Renderer(std::move(impl));
}

Result<MeshHandle> Renderer::createMesh(const MeshArrays& mesh) {
  StateGuard guard(m_impl->gl());
  Stopwatch watch;
  MeshBuffers buffers;
  auto r = buffers.upload(m_impl->gl(), mesh);
  m_impl->gl().BindVertexArray(0);
  m_impl->timings.uploadCpuMs = watch.elapsedMs();
  if (!r) return r.error();
  const MeshHandle handle{m_impl->nextId++};
  m_impl->meshes.emplace(handle.id, std::move(buffers));
  return handle;
}

Result<void> Renderer::updateMesh(MeshHandle mesh, const MeshUpdate& update) {
  const auto it = m_impl->meshes.find(mesh.id);
  if (it == m_impl->meshes.end()) {
    return Error{"renderer: updateMesh of mesh " + std::to_string(mesh.id) +
                 ", which this renderer does not hold"};
  }
  StateGuard guard(m_impl->gl());
  Stopwatch watch;
  auto r = it->second.update(m_impl->gl(), update);
  m_impl->timings.uploadCpuMs = watch.elapsedMs();
  return r;
}

void Renderer::destroyMesh(MeshHandle mesh) {
  m_impl->meshes.erase(mesh.id);
}

Result<TextureHandle> Renderer::createTexture(const Image8& image, TextureEncoding encoding) {
  StateGuard guard(m_impl->gl());
  gl::Texture texture;
  m_impl->gl().ActiveTexture(GL_TEXTURE0);
  if (auto r = uploadTexture(m_impl->gl(), texture, image, encoding); !r) return r.error();
  const TextureHandle handle{m_impl->nextId++};
  m_impl->textures.emplace(handle.id, std::move(texture));
  if (encoding != TextureEncoding::Srgb) m_impl->textureEncodings[handle.id] = encoding;
  return handle;
}

Result<void> Renderer::updateTexture(TextureHandle texture, const Image8& image) {
  const auto it = m_impl->textures.find(texture.id);
  if (it == m_impl->textures.end()) {
    return Error{"renderer: updateTexture of texture " + std::to_string(texture.id) +
                 ", which this renderer does not hold"};
  }
  StateGuard guard(m_impl->gl());
  m_impl->gl().ActiveTexture(GL_TEXTURE0);
  const auto encoding = m_impl->textureEncodings.find(texture.id);
  return uploadTexture(m_impl->gl(), it->second, image,
                       encoding == m_impl->textureEncodings.end() ? TextureEncoding::Srgb : encoding->second);
}

void Renderer::destroyTexture(TextureHandle texture) {
  m_impl->textures.erase(texture.id);
  m_impl->textureEncodings.erase(texture.id);
}

Result<void> Renderer::setMesh(const MeshArrays& mesh) {
  auto handle = createMesh(mesh);
  if (!handle) return handle.error();
  if (m_impl->singleMesh) destroyMesh(m_impl->singleMesh);
  m_impl->singleMesh = *handle;
  return {};
}

Result<void> Renderer::updateMesh(std::span<const Float3> positions, std::span<const Float3> normals,
                                  std::span<const Float4> tangents) {
  const auto it = m_impl->meshes.find(m_impl->singleMesh.id);
  if (it == m_impl->meshes.end()) return Error{"renderer: updateMesh before setMesh"};
  const std::size_t n = it->second.vertexCount();
  if (positions.size() != n || normals.size() != n || tangents.size() != n) {
    return Error{"renderer: updateMesh needs " + std::to_string(n) +
                 " positions, normals and tangents (the count given to setMesh)"};
  }
  return updateMesh(m_impl->singleMesh, {0, positions, normals, tangents, {}});
}

Result<void> Renderer::setBaseColor(const Image8& image) {
  if (m_impl->singleBaseColor) return updateTexture(m_impl->singleBaseColor, image);
  auto handle = createTexture(image);
  if (!handle) return handle.error();
  m_impl->singleBaseColor = *handle;
  return {};
}

Result<void> Renderer::setNormalMap(const Image8& image) {
  if (m_impl->singleNormalMap) {
    if (auto r = updateTexture(m_impl->singleNormalMap, image); !r) return r;
  } else {
    auto handle = createTexture(image);
    if (!handle) return handle.error();
    m_impl->singleNormalMap = *handle;
  }
  m_impl->singleNormalMapping = true;
  return {};
}

void Renderer::setNormalMapping(bool enabled) {
  m_impl->singleNormalMapping = enabled;
}

Result<Image8> Renderer::renderImage(const Scene& scene, int width, int height) {
  Impl& s = *m_impl;
  const gl::GlApi& g = s.gl();
  StateGuard guard(g);
  Stopwatch total;
  s.passes.beginFrame(g, s.settings.gpuTimers, s.settings.finishPasses);
  if (auto r = s.targets.ensure(g, width, height, s.settings.samples); !r) return r.error();
  if (auto r = s.renderFrame(scene, width, height, s.targets.outputFramebuffer(), 0, 0, true); !r) {
    s.passes.finishFrame();
    return r.error();
  }
  Result<Image8> image = Error{""};
  auto r = s.passes.run("readback", [&]() -> Result<void> {
    image = s.targets.readOutput(g);
    return image ? Result<void>{} : image.error();
  });
  s.timings.passes = s.passes.finishFrame();
  s.timings.totalCpuMs = total.elapsedMs();
  if (!r) return r.error();
  return image;
}

Result<void> Renderer::renderTo(const Scene& scene, const HostFramebuffer& target) {
  Impl& s = *m_impl;
  const gl::GlApi& g = s.gl();
  if (target.width <= 0 || target.height <= 0) return Error{"renderer: host viewport has no area"};
  StateGuard guard(g);
  Stopwatch total;
  g.BindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
  if (g.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    return Error{"renderer: host framebuffer " + std::to_string(target.framebuffer) + " is incomplete"};
  }
  s.passes.beginFrame(g, s.settings.gpuTimers, s.settings.finishPasses);
  auto r = s.renderFrame(scene, target.width, target.height, target.framebuffer, target.x, target.y,
                         target.clear, target.depth);
  s.timings.passes = s.passes.finishFrame();
  s.timings.totalCpuMs = total.elapsedMs();
  return r;
}

Result<FloatImage> Renderer::readFrame(FrameView view) {
  StateGuard guard(m_impl->gl());
  return m_impl->targets.readView(m_impl->gl(), view);
}

Result<TextureSpaceMaps> Renderer::readTextureSpaceMaps() {
  StateGuard guard(m_impl->gl());
  return m_impl->textureSpace.readMaps(m_impl->gl());
}

const RenderTimings& Renderer::lastTimings() const {
  return m_impl->timings;
}

}  // namespace tissue::render
