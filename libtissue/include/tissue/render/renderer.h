#pragma once
/// \file
/// The renderer core. It does not own a GL context: it is created with a getProcAddress
/// function (the host's or a tissue context's) and uses whatever context is current at each
/// call (the one it was created on, or one sharing objects with it). It draws either into its
/// own offscreen framebuffer, read back to an Image8, or into a host's framebuffer, and it
/// leaves the host's GL state as it found it (see renderTo).

#include <memory>
#include <span>

#include "tissue/core/image.h"
#include "tissue/core/result.h"
#include "tissue/core/types.h"
#include "tissue/gl/proc_address.h"
#include "tissue/gl/shader_library.h"
#include "tissue/render/scene.h"

namespace tissue::render {

/// A triangle mesh as plain arrays (copied at upload; not kept).
struct MeshArrays {
  std::span<const Float3> positions;    ///< #V, mm, world space
  std::span<const Float3> normals;      ///< #V unit normals
  std::span<const Float4> tangents;     ///< #V (unit T, handedness w = +-1); B = w * cross(N, T)
  std::span<const Float2> uvs;          ///< #V texture coordinates
  std::span<const Triangle> triangles;  ///< #F, counter-clockwise seen from outside
};

/// A framebuffer owned by the host, and where in it to draw.
struct HostFramebuffer {
  unsigned int framebuffer = 0;  ///< GL name (0 = the default framebuffer)
  int x = 0;                     ///< viewport origin, pixels
  int y = 0;                     ///< viewport origin, pixels
  int width = 0;                 ///< viewport size, pixels
  int height = 0;                ///< viewport size, pixels
  bool clear = true;             ///< clear colour and depth inside the viewport first
};

/// The cost of the last frame, per pass. GPU times come from GL_TIME_ELAPSED queries and are
/// negative when timers are off.
struct RenderTimings {
  double drawCpuMs = 0.0;      ///< ms, CPU time issuing the lit pass
  double drawGpuMs = -1.0;     ///< ms, GPU time of the lit pass
  double resolveGpuMs = -1.0;  ///< ms, GPU time of the MSAA resolve and readback (offscreen only)
  double readbackCpuMs = 0.0;  ///< ms, CPU time of resolve + glReadPixels + flip (offscreen only)
  double totalCpuMs = 0.0;     ///< ms, the whole call including waiting for the timers
  double uploadCpuMs = 0.0;    ///< ms, CPU time of the last setMesh/updateMesh
};

/// Creation settings.
struct RendererSettings {
  gl::ShaderLibrarySettings shaders;  ///< where GLSL comes from (embedded, or an override folder)
  int samples = 0;                    ///< MSAA samples of the offscreen target (0 or 1: none)
  bool gpuTimers = true;              ///< time passes with GL queries (waits for the GPU each frame)
};

/// Draws a lit, normal-mapped triangle mesh. Movable, not copyable. Every method needs the
/// renderer's context (or one sharing with it) current; so does destruction.
class Renderer {
 public:
  /// Loads GL through `getProcAddress` and builds the shader variants; the context must be
  /// current and GL 3.3 core or newer.
  static Result<Renderer> create(const gl::GetProcAddressFn& getProcAddress,
                                 const RendererSettings& settings = {});

  Renderer(Renderer&&) noexcept;
  Renderer& operator=(Renderer&&) noexcept;
  ~Renderer();

  /// Uploads a mesh, replacing the previous one. All arrays must have #V entries.
  Result<void> setMesh(const MeshArrays& mesh);
  /// Re-uploads only the deforming attributes (glBufferSubData); sizes must match setMesh.
  Result<void> updateMesh(std::span<const Float3> positions, std::span<const Float3> normals,
                          std::span<const Float4> tangents);
  /// Sets the base colour texture (sRGB-encoded, 1-4 channels; mipmapped, repeating).
  Result<void> setBaseColor(const Image8& image);
  /// Sets the tangent-space normal map (RGB = n * 0.5 + 0.5) and turns normal mapping on.
  Result<void> setNormalMap(const Image8& image);
  /// Turns normal mapping off (the interpolated vertex normals shade) or back on.
  void setNormalMapping(bool enabled);

  /// Renders into the renderer's own offscreen framebuffer and reads it back: RGBA8, rows
  /// top to bottom. `width` x `height` pixels.
  Result<Image8> renderImage(const Scene& scene, int width, int height);

  /// Renders into the host's framebuffer. Restores afterwards: draw/read framebuffer bindings,
  /// viewport, scissor box and test, program, vertex array, array buffer, active texture
  /// unit and the 2D textures of units 0 and 1, depth test/func/mask, cull face/mode, front
  /// face, blending, colour mask, clear colour and depth, FRAMEBUFFER_SRGB and multisample.
  Result<void> renderTo(const Scene& scene, const HostFramebuffer& target);

  /// Timings of the last render call.
  const RenderTimings& lastTimings() const;

 private:
  struct Impl;
  explicit Renderer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> m_impl;
};

}  // namespace tissue::render
