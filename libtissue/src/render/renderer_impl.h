#pragma once
// The renderer's state, shared by renderer.cpp (creation, resources, the single-mesh API) and
// frame.cpp (the frame: passes in order).
#include <map>
#include <memory>
#include <vector>

#include "frame_targets.h"
#include "host_depth.h"
#include "mesh_buffers.h"
#include "methods/lit.h"
#include "methods/parallax.h"
#include "methods/ray_march.h"
#include "methods/separable_sss.h"
#include "methods/texture_space.h"
#include "pass_timers.h"
#include "post_passes.h"
#include "shadow_maps.h"
#include "tissue/render/renderer.h"

namespace tissue::render {

struct Renderer::Impl {
  std::shared_ptr<const gl::GlApi> api;
  RendererSettings settings;
  // The shading methods (a closed set: one member each) and the shared passes.
  LitMethod lit;
  SeparableMethod separable;
  TextureSpaceMethod textureSpace;
  RayMarchMethod rayMarch;
  ParallaxMethod parallax;
  ShadowMaps shadows;
  PostPasses post;
  HostDepthPass hostDepth;
  // Resources by handle id.
  std::map<std::uint32_t, MeshBuffers> meshes;
  std::map<std::uint32_t, gl::Texture> textures;
  std::map<std::uint32_t, TextureEncoding> textureEncodings;  // those not Srgb (updateTexture keeps them)
  std::uint32_t nextId = 1;
  gl::Texture defaultBaseColor;
  gl::VertexArray emptyVertexArray;
  // The single-mesh API's object.
  MeshHandle singleMesh;
  TextureHandle singleBaseColor, singleNormalMap;
  bool singleNormalMapping = false;
  // Per frame.
  FrameTargets targets;
  PassTimers passes;
  RenderTimings timings;

  const gl::GlApi& gl() const { return *api; }

  /// Every pass up to and including the HDR composite, into the frame targets, then the tone
  /// map into the caller's framebuffer at (x, y). `depth`: HostDepth::TestAndWrite reads that
  /// framebuffer's depth before the geometry passes and writes it in the tone map.
  /// Defined in frame.cpp.
  Result<void> renderFrame(const Scene& scene, int width, int height, GLuint framebuffer, int x, int y,
                           bool writeBackground, HostDepth depth = HostDepth::Ignore);
};

}  // namespace tissue::render
