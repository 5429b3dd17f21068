// One frame: shadow:<light> -> clear -> host-depth (HostDepth::TestAndWrite) -> one geometry pass per shading
// method present -> resolve (MSAA) -> method post passes -> composite -> tonemap. Every pass is named and
// timed.
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <string>

#include "camera_math.h"
#include "renderer_impl.h"

namespace tissue::render {
namespace {

constexpr int kMaxObjects = 2047;  // ids are stored in half floats, exact up to 2048
constexpr std::size_t kMethodCount = std::variant_size_v<MethodSettings>;

// The frame's objects resolved to GPU names, grouped by method (index = ShadingMethod).
struct ResolvedObjects {
  std::array<std::vector<ObjectDraw>, kMethodCount> byMethod;
  std::vector<ShadowCaster> casters;  // every visible object's mesh and model, for the shadow passes
  glm::vec3 lo{0.0f}, hi{0.0f};       // mm, their world bounds
  int count = 0;
};

// The textures a method's settings name, in the order of ObjectDraw::methodTextures.
std::array<TextureHandle, kMaxMethodTextures> methodTextureHandles(const MethodSettings& method) {
  std::array<TextureHandle, kMaxMethodTextures> out{};
  if (const auto* p = std::get_if<ParallaxSettings>(&method)) {  // opacity map, inner layers
    out[0] = p->opacityMap;
    for (std::size_t i = 0; i < p->layers.size() && i + 1 < out.size(); ++i)
      out[i + 1] = p->layers[i].base;
  }
  if (const auto* r = std::get_if<RayMarchSettings>(&method)) {  // subsurface maps
    for (std::size_t i = 0; i < r->subsurfaceMaps.size() && i < out.size(); ++i)
      out[i] = r->subsurfaceMaps[i];
  }
  return out;
}

Result<ResolvedObjects> resolveObjects(std::span<const SceneObject> objects,
                                       const std::map<std::uint32_t, MeshBuffers>& meshes,
                                       const std::map<std::uint32_t, gl::Texture>& textures,
                                       GLuint defaultBase) {
  if (objects.size() > static_cast<std::size_t>(kMaxObjects)) {
    return Error{"renderer: the scene has " + std::to_string(objects.size()) + " objects; at most " +
                 std::to_string(kMaxObjects) + " are supported"};
  }
  ResolvedObjects out;
  out.count = static_cast<int>(objects.size());
  bool first = true;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const SceneObject& o = objects[i];
    if (!o.visible) continue;
    const auto mesh = meshes.find(o.mesh.id);
    if (mesh == meshes.end() || mesh->second.empty()) {
      return Error{"renderer: scene object " + std::to_string(i) + " names mesh " +
                   std::to_string(o.mesh.id) + ", which this renderer does not hold (createMesh it first)"};
    }
    auto transform = makeModelTransform(o.model);
    if (!transform)
      return Error{"renderer: scene object " + std::to_string(i) + ": " + transform.error().message};
    ObjectDraw d{&o, &mesh->second, defaultBase, 0, static_cast<float>(i + 1)};
    d.transform = *transform;
    transformBounds(d.transform.model, mesh->second.lo(), mesh->second.hi(), d.lo, d.hi);
    for (auto [handle, name, what] : {std::tuple{o.baseColor, &d.baseColor, "baseColor"},
                                      std::tuple{o.normalMap, &d.normalMap, "normalMap"}}) {
      if (!handle) continue;
      const auto t = textures.find(handle.id);
      if (t == textures.end()) {
        return Error{"renderer: scene object " + std::to_string(i) + "'s " + what + " names texture " +
                     std::to_string(handle.id) + ", which this renderer does not hold"};
      }
      *name = t->second.id();
    }
    const auto methodHandles = methodTextureHandles(o.method);
    for (std::size_t k = 0; k < methodHandles.size(); ++k) {
      if (!methodHandles[k]) continue;
      const auto t = textures.find(methodHandles[k].id);
      if (t == textures.end()) {
        return Error{"renderer: scene object " + std::to_string(i) + "'s " +
                     std::string(shadingMethodName(shadingMethod(o.method))) + " settings name texture " +
                     std::to_string(methodHandles[k].id) + ", which this renderer does not hold"};
      }
      d.methodTextures[k] = t->second.id();
    }
    out.byMethod[o.method.index()].push_back(d);
    out.casters.push_back({&mesh->second, d.transform.model});
    out.lo = first ? d.lo : glm::min(out.lo, d.lo);
    out.hi = first ? d.hi : glm::max(out.hi, d.hi);
    first = false;
  }
  return out;
}

// The "clear" pass: every geometry target to zero (no coverage, no id), depth to far.
Result<void> clearTargets(const FrameContext& frame) {
  return frame.passes.run("clear", [&]() -> Result<void> {
    const gl::GlApi& g = frame.gl;
    beginGeometryPass(frame);
    g.ClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    g.ClearDepth(1.0);
    g.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    // Without separable objects the blurred diffuse stays zero for the composite.
    g.BindFramebuffer(GL_FRAMEBUFFER, frame.targets.blurredFramebuffer());
    g.Clear(GL_COLOR_BUFFER_BIT);
    return gl::checkGlError(g, "renderer: clear pass");
  });
}

}  // namespace

Result<void> Renderer::Impl::renderFrame(const Scene& scene, int width, int height, GLuint framebuffer, int x,
                                         int y, bool writeBackground, HostDepth depth) {
  const gl::GlApi& g = gl();
  // Step 1: the objects (the single-mesh API's when the scene names none) and the lights.
  std::vector<SceneObject> single;
  std::span<const SceneObject> objects = scene.objects;
  if (objects.empty()) {
    if (!singleMesh) return Error{"renderer: no mesh; call setMesh first, or give the scene objects"};
    single.push_back({singleMesh, singleBaseColor, singleNormalMapping ? singleNormalMap : TextureHandle{},
                      scene.material, LitSettings{}, true, kIdentityModel});
    objects = single;
  }
  auto resolved = resolveObjects(objects, meshes, textures, defaultBaseColor.id());
  if (!resolved) return resolved.error();
  const glm::vec3 centre = 0.5f * (resolved->lo + resolved->hi);
  const float radius = std::max(0.5f * glm::length(resolved->hi - resolved->lo), 1e-3f);
  auto lights = makeLightFrame(scene.lights, centre, radius, settings.shadowMapSize);
  if (!lights) return lights.error();
  if (auto r = targets.ensure(g, width, height, settings.samples); !r) return r;
  const Camera& c = scene.camera;
  FrameContext frame{g,
                     scene,
                     width,
                     height,
                     viewProjection(c, static_cast<float>(width) / static_cast<float>(height)),
                     glm::normalize(toGlm(c.target) - toGlm(c.eye)),
                     *lights,
                     shadows.texture(),
                     targets,
                     passes,
                     emptyVertexArray.id(),
                     resolved->count};
  // Step 2: shadow maps, one pass per shadow-casting light.
  for (int i = 0; i < lights->count; ++i) {
    if (lights->shadowLayer[static_cast<std::size_t>(i)] < 0) continue;
    auto r = passes.run("shadow:" + std::to_string(i),
                        [&] { return shadows.draw(g, *lights, i, resolved->casters); });
    if (!r) return r;
  }
  // Step 3: geometry, one pass (or more) per shading method present; one switch (STYLE rule 5).
  if (auto r = clearTargets(frame); !r) return r;
  const bool hostDepthOn = depth == HostDepth::TestAndWrite;
  if (hostDepthOn) {
    if (auto r = hostDepth.load(frame, framebuffer, x, y); !r) return r;
  }
  for (std::size_t m = 0; m < kMethodCount; ++m) {
    const std::span<const ObjectDraw> group = resolved->byMethod[m];
    if (group.empty()) continue;
    Result<void> r;
    switch (static_cast<ShadingMethod>(m)) {
      case ShadingMethod::Lit:
        r = lit.draw(frame, group);
        break;
      case ShadingMethod::Separable:
        r = separable.draw(frame, group);
        break;
      case ShadingMethod::TextureSpace:
        r = textureSpace.draw(frame, group);
        break;
      case ShadingMethod::RayMarch:
        r = rayMarch.draw(frame, group);
        break;
      case ShadingMethod::Parallax:
        r = parallax.draw(frame, group);
        break;
    }
    if (!r) return r;
  }
  // Step 4: MSAA resolve, then the methods' screen-space passes on single-sample textures.
  if (targets.samples() > 1) {
    auto r = passes.run("resolve", [&] {
      targets.resolve(g);
      return gl::checkGlError(g, "renderer: resolve");
    });
    if (!r) return r;
  }
  const auto& separableGroup = resolved->byMethod[static_cast<std::size_t>(ShadingMethod::Separable)];
  if (!separableGroup.empty()) {
    if (auto r = separable.post(frame, separableGroup); !r) return r;
  }
  if (!resolved->byMethod[static_cast<std::size_t>(ShadingMethod::TextureSpace)].empty()) {
    if (auto r = textureSpace.post(frame, !separableGroup.empty()); !r) return r;
  }
  // Step 5: HDR composite and tone map into the caller's framebuffer.
  if (auto r = post.composite(frame); !r) return r;
  return post.tonemap(frame, framebuffer, x, y, writeBackground && !hostDepthOn, hostDepthOn);
}

}  // namespace tissue::render
