// TextureSpaceRenderer: texture-space diffusion of one mesh drawn as instances, offscreen.
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "../camera_math.h"
#include "../mesh_buffers.h"
#include "../state_guard.h"
#include "../textures.h"
#include "texture_space_passes.h"
#include "tissue/gl/program.h"
#include "tissue/render/texture_space.h"

namespace tissue::render {
namespace {

Mat4 toMat4(const glm::mat4& m) {
  Mat4 out;
  std::memcpy(out.data(), glm::value_ptr(m), sizeof(float) * 16);
  return out;
}

TextureSpaceDiffusionSettings passSettings(const TsdSettings& s, float referenceMm) {
  TextureSpaceDiffusionSettings p;
  p.gaussians = s.gaussians;
  p.irradiance = {s.cull, s.clip, s.depthSize, s.clipD, referenceMm};
  p.blurHalfTaps = s.blurHalfTaps;
  return p;
}

}  // namespace

struct TextureSpaceRenderer::Impl {
  std::shared_ptr<const gl::GlApi> api;
  TextureSpaceRendererSettings settings;
  TextureSpaceDiffusion tsd;
  MeshBuffers mesh;
  gl::Texture baseColor;
  gl::Framebuffer target;
  gl::Renderbuffer color, depth;
  int width = 0, height = 0;
  float texelsPerMm = 0.0f;
  Float3 lo, hi;  // mm, the mesh's bounds
  IrradianceFrame lastFrame;

  const gl::GlApi& gl() const { return *api; }

  // d_ref (mm): given, or one texel of the full map per pixel (a pixel spans 2 d tan(fov / 2) / H
  // mm at distance d).
  float referenceDistance(const Scene& scene, int imageHeight, const TsdSettings& s) const {
    if (s.referenceDistanceMm > 0.0f) return s.referenceDistanceMm;
    const float tanHalf = std::tan(glm::radians(scene.camera.verticalFovDeg) * 0.5f);
    return texelsPerMm > 0.0f ? float(imageHeight) / (2.0f * tanHalf * texelsPerMm) : 0.0f;
  }

  void bounds(std::span<const Float3> p) {
    lo = hi = p.empty() ? Float3{} : p[0];
    for (const Float3& v : p) {
      lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
      hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
    }
  }

  Result<void> ensureTarget(int w, int h) {
    if (w <= 0 || h <= 0 || w > 8192 || h > 8192)
      return Error{"texture space: image size " + std::to_string(w) + "x" + std::to_string(h) +
                   " is outside 1..8192"};
    if (w == width && h == height) return {};
    const gl::GlApi& g = gl();
    target = gl::Framebuffer::create(g);
    color = gl::Renderbuffer::create(g);
    depth = gl::Renderbuffer::create(g);
    g.BindRenderbuffer(GL_RENDERBUFFER, color.id());
    g.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, w, h);
    g.BindRenderbuffer(GL_RENDERBUFFER, depth.id());
    g.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, w, h);
    g.BindFramebuffer(GL_FRAMEBUFFER, target.id());
    g.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color.id());
    g.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth.id());
    if (g.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      return Error{"texture space: the image framebuffer is incomplete"};
    width = w, height = h;
    return {};
  }

  // The frame's matrices, light and bounds for one instance.
  IrradianceFrame frameOf(const Scene& scene, float aspect, Float3 offset) const {
    const Camera& c = scene.camera;
    IrradianceFrame f;
    f.view = toMat4(glm::lookAt(toGlm(c.eye), toGlm(c.target), toGlm(c.up)));
    f.projection = toMat4(glm::perspective(glm::radians(c.verticalFovDeg), aspect, c.nearMm, c.farMm));
    f.eye = c.eye;
    f.boundsLo = lo, f.boundsHi = hi;
    f.offsetMm = offset;
    // The first light of the scene (texture-space diffusion here takes one; no shadows). A
    // directional light becomes a point far along its direction.
    if (!scene.lights.empty()) {
      const Light& l = scene.lights.front();
      f.lightPosition = l.type == LightType::Point
                            ? l.positionMm
                            : Float3{c.target.x - l.direction.x * 1e6f, c.target.y - l.direction.y * 1e6f,
                                     c.target.z - l.direction.z * 1e6f};
      f.lightRadiance = {l.color.x * l.intensity, l.color.y * l.intensity, l.color.z * l.intensity};
    }
    f.ambient = scene.material.ambient;
    return f;
  }

  TsdSurface surfaceOf(const Scene& scene, float aspect) const {
    TsdSurface s;
    s.viewProjection = toMat4(viewProjection(scene.camera, aspect));
    s.cameraPosition = scene.camera.eye;
    s.specular = scene.material.specular;
    s.shininess = scene.material.shininess;
    s.exposure = scene.exposure;
    s.baseColor = baseColor.id();
    return s;
  }

  void clearTarget(const Scene& scene) {
    const gl::GlApi& g = gl();
    g.BindFramebuffer(GL_FRAMEBUFFER, target.id());
    g.Viewport(0, 0, width, height);
    g.Disable(GL_SCISSOR_TEST);
    g.Disable(GL_FRAMEBUFFER_SRGB);
    g.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    g.DepthMask(GL_TRUE);
    g.ClearColor(scene.background.x, scene.background.y, scene.background.z, 1.0f);
    g.ClearDepth(1.0);
    g.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }

  Result<Image8> readImage() {
    const gl::GlApi& g = gl();
    Image8 image(width, height, 4);
    g.BindFramebuffer(GL_READ_FRAMEBUFFER, target.id());
    g.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    g.PixelStorei(GL_PACK_ALIGNMENT, 4);
    g.ReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
    if (auto r = gl::checkGlError(g, "texture space: image readback"); !r) return r.error();
    flipVertically(image);
    return image;
  }
};

TextureSpaceRenderer::TextureSpaceRenderer(std::unique_ptr<Impl> impl) : m_impl(std::move(impl)) {}
TextureSpaceRenderer::TextureSpaceRenderer(TextureSpaceRenderer&&) noexcept = default;
TextureSpaceRenderer& TextureSpaceRenderer::operator=(TextureSpaceRenderer&&) noexcept = default;
TextureSpaceRenderer::~TextureSpaceRenderer() = default;

Result<TextureSpaceRenderer> TextureSpaceRenderer::create(const gl::GetProcAddressFn& getProcAddress,
                                                          const TextureSpaceRendererSettings& settings) {
  auto api = gl::loadGl(getProcAddress);
  if (!api) return Error{"texture space: " + api.error().message};
  auto impl = std::make_unique<Impl>();
  impl->api = std::move(*api);
  impl->settings = settings;
  const gl::GlApi& g = impl->gl();
  StateGuard guard(g);
  const gl::ShaderLibrary library(settings.shaders);
  auto tsd = TextureSpaceDiffusion::create(g, library, settings.maxMapSize);
  if (!tsd) return tsd.error();
  impl->tsd = std::move(*tsd);
  g.ActiveTexture(GL_TEXTURE0);
  if (auto r = uploadSolidTexture(g, impl->baseColor, 196, 112, 104); !r) return r.error();
  return TextureSpaceRenderer(std::move(impl));
}

Result<void> TextureSpaceRenderer::setMesh(const MeshArrays& mesh, float texelsPerMm) {
  StateGuard guard(m_impl->gl());
  m_impl->texelsPerMm = texelsPerMm;
  m_impl->bounds(mesh.positions);
  return m_impl->mesh.upload(m_impl->gl(), mesh);
}

Result<void> TextureSpaceRenderer::updateMesh(std::span<const Float3> positions,
                                              std::span<const Float3> normals,
                                              std::span<const Float4> tangents) {
  StateGuard guard(m_impl->gl());
  m_impl->bounds(positions);
  MeshUpdate update;
  update.positions = positions;
  update.normals = normals;
  update.tangents = tangents;
  return m_impl->mesh.update(m_impl->gl(), update);
}

Result<void> TextureSpaceRenderer::setBaseColor(const Image8& image) {
  StateGuard guard(m_impl->gl());
  m_impl->gl().ActiveTexture(GL_TEXTURE0);
  return uploadTexture(m_impl->gl(), m_impl->baseColor, image);
}

Result<Image8> TextureSpaceRenderer::renderImage(const Scene& scene, int width, int height,
                                                 const TsdSettings& settings,
                                                 std::span<const Float3> instanceOffsetsMm) {
  Impl& s = *m_impl;
  const gl::GlApi& g = s.gl();
  if (s.mesh.empty()) return Error{"texture space: no mesh; call setMesh first"};
  StateGuard guard(g);
  if (auto r = s.ensureTarget(width, height); !r) return r.error();
  const float aspect = float(width) / float(height);
  const auto pass = passSettings(settings, s.referenceDistance(scene, height, settings));
  const TsdSurface surface = s.surfaceOf(scene, aspect);
  s.clearTarget(scene);
  const Float3 origin{};
  const std::span<const Float3> offsets =
      instanceOffsetsMm.empty() ? std::span(&origin, 1) : instanceOffsetsMm;
  // Instance by instance, as Jimenez et al. render their heads: the maps are shared.
  for (const Float3& offset : offsets) {
    s.lastFrame = s.frameOf(scene, aspect, offset);
    if (auto r = s.tsd.diffuse(s.mesh.vertexArray(), s.mesh.indexCount(), s.lastFrame, pass, true); !r)
      return r.error();
    g.BindFramebuffer(GL_FRAMEBUFFER, s.target.id());
    g.Viewport(0, 0, width, height);
    if (auto r = s.tsd.drawFinal(s.mesh.vertexArray(), s.mesh.indexCount(), s.lastFrame, surface,
                                 s.tsd.chainMaps(pass));
        !r)
      return r.error();
  }
  return s.readImage();
}

}  // namespace tissue::render
