#pragma once
/// \file
/// The renderer: a pipeline of named, timed passes over a scene of objects, each shaded by its
/// own method (tissue/render/shading.h). It does not own a GL context: it is created with a
/// getProcAddress function (the host's or a tissue context's) and uses whatever context is
/// current at each call (the one it was created on, or one sharing objects with it). It draws
/// either into its own offscreen framebuffer, read back to an Image8, or into a host's
/// framebuffer, and it leaves the host's GL state as it found it (see renderTo).
///
/// The frame: shadow:<light> (one depth pass per shadow-casting light) -> clear -> host-depth
/// (renderTo with HostDepth::TestAndWrite only) -> one pass per
/// shading method present (lit, separable:geometry, ...) into linear HDR targets -> resolve
/// (MSAA only) -> method post passes (separable:resolve with MSAA, separable:blur-x,
/// separable:blur-y, and separable:blur-x:r / blur-y:r per further kernel component) -> composite (HDR,
/// RGBA16F) -> tonemap (Reinhard, sRGB8) -> readback (offscreen only). Texture-space objects add
/// texture-space:irradiance, :blur and :final per object in the geometry step, and
/// texture-space:copy after the blur when no separable object is present.

#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "tissue/core/image.h"
#include "tissue/core/result.h"
#include "tissue/core/types.h"
#include "tissue/gl/proc_address.h"
#include "tissue/gl/shader_library.h"
#include "tissue/render/scene.h"

namespace tissue::render {

/// A triangle mesh as plain arrays (copied at upload; not kept).
struct MeshArrays {
  std::span<const Float3> positions;    ///< #V, mm, object space (SceneObject::model takes it to world)
  std::span<const Float3> normals;      ///< #V unit normals
  std::span<const Float4> tangents;     ///< #V (unit T, handedness w = +-1); B = w * cross(N, T)
  std::span<const Float2> uvs;          ///< #V texture coordinates
  std::span<const Triangle> triangles;  ///< #F, counter-clockwise seen from outside
  /// Optional: #V local planes (N_S unit, d mm) of subsurface texture mapping (François eq. 14),
  /// for the ray-marching methods; empty = none (attribute 4 reads (0, 0, 1, 0)).
  std::span<const Float4> planes;
};

/// What changed in a deforming mesh: each non-empty span replaces that attribute for vertices
/// [firstVertex, firstVertex + size) with glBufferSubData; empty spans leave it as it is.
struct MeshUpdate {
  std::size_t firstVertex = 0;        ///< index of the first vertex replaced
  std::span<const Float3> positions;  ///< mm
  std::span<const Float3> normals;    ///< unit
  std::span<const Float4> tangents;   ///< (unit T, w = +-1)
  std::span<const Float4> planes;     ///< (N_S, d mm); the mesh must have been created with planes
};

/// What renderTo does with the host framebuffer's depth buffer.
enum class HostDepth {
  /// Neither read nor written: the tissue is drawn over whatever the host drew in the viewport.
  Ignore,
  /// (a) The tissue is depth-tested against the host's depth buffer as the host left it (an
  /// instrument the host drew in front hides the tissue), and (b) the tissue's depth is written
  /// into it where tissue is visible, so that the host can draw afterwards with its depth test
  /// (a floor drawn later stays hidden behind the tissue). Only pixels covered by tissue get
  /// colour and depth (HostFramebuffer::clear is ignored: as clear = false); elsewhere the
  /// host's colour and depth stay as they are.
  ///
  /// Contract: the scene's camera must be the host's projection for that viewport: the same
  /// view (eye, target, up), vertical field of view, aspect (= width / height of the
  /// viewport), near and far planes (a glm::perspective-style projection), and the host's depth
  /// is conventional (nearer is smaller, cleared to 1, drawn with GL_LESS or GL_LEQUAL, the same
  /// glDepthRange as the renderer's passes, which use the current one). The host framebuffer
  /// needs a depth attachment of 16, 24 or 32 bits (unsigned normalised, with or without 8
  /// stencil bits) or 32-bit float (with or without stencil); it may be multisampled. The host's
  /// depth is copied by glBlitFramebuffer into a matching single-sample depth texture (its
  /// format queried with glGetFramebufferAttachmentParameteriv), never read back to the CPU, and
  /// a full-screen pass writes it into the renderer's own depth buffer (MSAA or not) before the
  /// geometry passes ("host-depth"); the tone map writes gl_FragDepth from the renderer's depth
  /// (the nearest sample with MSAA) where covered and discards elsewhere. No glFinish.
  TestAndWrite,
};

/// A framebuffer owned by the host, and where in it to draw.
struct HostFramebuffer {
  unsigned int framebuffer = 0;  ///< GL name (0 = the default framebuffer)
  int x = 0;                     ///< viewport origin, pixels
  int y = 0;                     ///< viewport origin, pixels
  int width = 0;                 ///< viewport size, pixels
  int height = 0;                ///< viewport size, pixels
  /// Fill the viewport's background too; false: only pixels covered by an object are written.
  /// Ignored (as false) with HostDepth::TestAndWrite.
  bool clear = true;
  HostDepth depth = HostDepth::Ignore;  ///< the host's depth buffer: ignored, or tested and written
};

/// One pass of the last frame. GPU time comes from a GL_TIME_ELAPSED query and is -1 when
/// timers are off or the driver's result is impossible (longer than the wall clock).
struct PassTiming {
  std::string name;     ///< e.g. "shadow:0", "lit", "separable:blur-x", "tonemap"
  double cpuMs = 0.0;   ///< ms, CPU time issuing the pass
  double gpuMs = -1.0;  ///< ms, GPU time of the pass
  /// The scene object (index in Scene::objects) whose work the whole pass is (texture space's and
  /// parallax's per-object maps); -1: a pass of the frame (shadows, clear, tone map), of a method
  /// as a whole (separable's screen-space blurs, texture space's copy: paid once whatever the
  /// number of its objects), or one that draws several objects (`issued`).
  int object = -1;
  /// A pass that draws several objects (lit, separable's geometry, the ray march): each object's
  /// CPU ms issuing its draw, in draw order (without a finish between them, which on llvmpipe
  /// costs ~2 ms a pass). On llvmpipe the vertex work runs at issue, so this is an object's fixed
  /// cost; the rest of the pass (rasterisation, the pass's finish) is left for the caller to
  /// share (scene::framePassCosts, issue 16).
  std::vector<std::pair<int, double>> issued;
};

/// The cost of the last frame, pass by pass, in execution order.
struct RenderTimings {
  std::vector<PassTiming> passes;
  double totalCpuMs = 0.0;   ///< ms, the whole call including waiting for the timers
  double uploadCpuMs = 0.0;  ///< ms, CPU time of the last mesh upload or update
  /// The pass named `name`, or nullptr.
  const PassTiming* find(const std::string& name) const;
};

/// How a texture's 8-bit values are read.
enum class TextureEncoding {
  /// Colour (base colour; shaders decode sRGB themselves) and normal maps: mipmapped, trilinear,
  /// repeating.
  Srgb,
  /// Data read as stored, 0..1 linear (e.g. the ray-march method's subsurface maps of layer
  /// depths): bilinear without mip-maps (a mip level would average depths), clamped at the edges.
  LinearData,
};

/// Creation settings.
struct RendererSettings {
  gl::ShaderLibrarySettings shaders;  ///< where GLSL comes from (embedded, or an override folder)
  int samples = 0;                    ///< MSAA samples of the geometry passes (0 or 1: none)
  /// Time passes with GL queries. Off by default: collecting them waits for the GPU at the end of
  /// every frame, which stalls a host's frame; benchmarks turn them on.
  bool gpuTimers = false;
  /// Benchmarks only: glFinish before and after every pass, so that CPU times measure each pass
  /// to completion on lazy rasterisers (llvmpipe). It stalls the pipeline: never in a host frame.
  bool finishPasses = false;
  int shadowMapSize = 1024;  ///< pixels, square, per shadow-casting light
};

/// An intermediate target of the last frame, for inspection and CPU references.
enum class FrameView {
  Radiance,  ///< linear HDR radiance without the separable diffuse (RGB; a = 1 where covered)
  /// separable objects' diffuse radiance before the blur, texture-space objects' diffused
  /// diffuse radiance (RGB; a = object id, 0 = none)
  Diffuse,
  BlurredDiffuse,  ///< the same after both blur passes, which leave non-separable ids as they are (RGB; a =
                   ///< id)
  Position,        ///< world position (xyz, mm) and view depth (w, mm; 0 where nothing was drawn)
};

/// A float RGBA image, rows top to bottom.
struct FloatImage {
  int width = 0;
  int height = 0;
  std::vector<Float4> pixels;  ///< width * height
  const Float4& at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
};

/// The texture-space maps of the last texture-space object drawn: the used T x T texels of each,
/// rows in increasing v (texel (i, j) at uv = ((i + 0.5) / T, (j + 0.5) / T) / s). For CPU
/// references of texture-space diffusion's own model.
struct TextureSpaceMaps {
  int size = 0;           ///< T, texels
  int maxSize = 0;        ///< T_max, texels
  FloatImage irradiance;  ///< rgb albedo^p x irradiance, a = 1 where drawn and not culled
  FloatImage stretch;   ///< r, g: |dP/du|, |dP/dv|, mm per UV unit; b: sqrt(|dP/du x dP/dv|), mm per UV unit
  FloatImage position;  ///< xyz world position, mm; w = 1 where drawn (culled and clipped texels too)
  FloatImage diffused;  ///< rgb sum_i w_i G(v_i) * irradiance (premultiplied by a), a = coverage
};

/// Draws scenes of deforming objects. Movable, not copyable. Every method needs the renderer's
/// context (or one sharing with it) current; so does destruction.
class Renderer {
 public:
  /// Loads GL through `getProcAddress` and builds every method's shaders; the context must be
  /// current and GL 3.3 core or newer.
  static Result<Renderer> create(const gl::GetProcAddressFn& getProcAddress,
                                 const RendererSettings& settings = {});

  Renderer(Renderer&&) noexcept;
  Renderer& operator=(Renderer&&) noexcept;
  ~Renderer();

  /// Uploads a mesh (one buffer per attribute). All arrays must have #V entries.
  Result<MeshHandle> createMesh(const MeshArrays& mesh);
  /// Re-uploads what changed of a deforming mesh (glBufferSubData of the given ranges only).
  Result<void> updateMesh(MeshHandle mesh, const MeshUpdate& update);
  /// Frees a mesh; scenes must no longer name it.
  void destroyMesh(MeshHandle mesh);
  /// Uploads a texture (1-4 channels). Colour textures are sRGB-encoded (mipmapped, repeating);
  /// data textures take TextureEncoding::LinearData.
  Result<TextureHandle> createTexture(const Image8& image, TextureEncoding encoding = TextureEncoding::Srgb);
  /// Replaces a texture's image (keeping the encoding it was created with).
  Result<void> updateTexture(TextureHandle texture, const Image8& image);
  /// Frees a texture; scenes must no longer name it.
  void destroyTexture(TextureHandle texture);

  /// Single-mesh API: uploads the mesh drawn when a scene has no objects.
  Result<void> setMesh(const MeshArrays& mesh);
  /// Single-mesh API: re-uploads positions, normals and tangents; sizes must match setMesh.
  Result<void> updateMesh(std::span<const Float3> positions, std::span<const Float3> normals,
                          std::span<const Float4> tangents);
  /// Single-mesh API: the base colour texture (sRGB-encoded, 1-4 channels; mipmapped, repeating).
  Result<void> setBaseColor(const Image8& image);
  /// Single-mesh API: the tangent-space normal map (RGB = n * 0.5 + 0.5); turns normal mapping on.
  Result<void> setNormalMap(const Image8& image);
  /// Single-mesh API: turns normal mapping off (the interpolated vertex normals shade) or on.
  void setNormalMapping(bool enabled);

  /// Renders into the renderer's own offscreen framebuffer and reads it back: RGBA8, rows
  /// top to bottom. `width` x `height` pixels.
  Result<Image8> renderImage(const Scene& scene, int width, int height);

  /// Renders into the host's framebuffer: the tone-map pass writes its viewport; the host's
  /// depth buffer is ignored or tested and written (HostFramebuffer::depth, HostDepth).
  ///
  /// GL state contract (renderTo, renderImage and every other call): what the renderer changes
  /// it saves first and restores before returning, whether the call succeeds or fails:
  /// - bindings: draw and read framebuffer, renderbuffer, program, vertex array, array buffer,
  ///   pixel pack and unpack buffers; the active texture unit; on units 0-7 the 2D, 2D-array
  ///   and 2D-multisample textures and the sampler object (the renderer's passes use none);
  /// - viewport, scissor box, scissor test;
  /// - depth test, depth func, depth write mask, clear depth;
  /// - cull face (enable), cull face mode, front face; polygon mode (the passes draw GL_FILL);
  /// - blending (enable), blend functions and equations (RGB and alpha), colour write mask,
  ///   clear colour;
  /// - FRAMEBUFFER_SRGB, MULTISAMPLE;
  /// - enables the passes turn off and restore: stencil test, polygon offset fill,
  ///   sample alpha-to-coverage, sample coverage, rasterizer discard, primitive restart, colour
  ///   logic op, CLIP_DISTANCE0-5;
  /// - pixel store: pack alignment, unpack alignment, unpack row length, unpack skip pixels and
  ///   rows (the passes upload with 4, 0, 0, 0).
  /// Not touched: the depth range (used as it is), stencil functions and masks, blend colour,
  /// the host framebuffer's draw and read buffers, vertex-array contents, uniform buffers, the
  /// host's queries (with RendererSettings::gpuTimers on, no GL_TIME_ELAPSED query of the host
  /// may be active). Only the host's viewport rectangle of its colour buffer (and of its depth
  /// buffer with HostDepth::TestAndWrite) is written.
  Result<void> renderTo(const Scene& scene, const HostFramebuffer& target);

  /// Reads an intermediate target of the last frame (float RGBA, rows top to bottom).
  Result<FloatImage> readFrame(FrameView view);
  /// Reads the texture-space maps of the last texture-space object drawn (a debugging hook for
  /// CPU references); an Error before any texture-space object was drawn.
  Result<TextureSpaceMaps> readTextureSpaceMaps();

  /// Timings of the last render call.
  const RenderTimings& lastTimings() const;

 private:
  struct Impl;
  explicit Renderer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> m_impl;
};

}  // namespace tissue::render
