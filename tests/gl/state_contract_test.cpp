// The GL state contract of Renderer::renderTo (renderer.h): every state the comment lists is set
// to a value other than GL's default, renderTo runs (HostDepth::TestAndWrite and Ignore, MSAA on
// and off, one object of each shading method, a shadow-casting light), and every value must
// come back unchanged (glGet*). Hostile values that would break a pass that relied on them
// (stencil test with GL_NEVER, polygon mode GL_LINE, rasterizer discard, a sample coverage of 0,
// a colour mask, clip distances, sampler objects, a bound pixel-unpack buffer) must not change
// the image either.
#include <cstdio>
#include <string>
#include <vector>

#include "embedding_scene.h"
#include "gl_test_support.h"
#include "image_compare.h"
#include "tissue/gl/gl_api.h"

namespace tissue::test {
namespace {

constexpr int kWidth = 128, kHeight = 96, kUnits = 8;

// One named value of the listed state.
struct Entry {
  std::string name;
  std::vector<double> values;
  bool operator==(const Entry&) const = default;
};

// Every state renderer.h's renderTo comment lists, read back.
std::vector<Entry> snapshot(const gl::GlApi& g) {
  std::vector<Entry> out;
  const auto ints = [&](const std::string& name, GLenum pname, int count) {
    GLint v[4] = {};
    g.GetIntegerv(pname, v);
    out.push_back({name, std::vector<double>(v, v + count)});
  };
  const auto enabled = [&](const std::string& name, GLenum cap) {
    out.push_back({name, {double(g.IsEnabled(cap))}});
  };
  ints("draw framebuffer", GL_DRAW_FRAMEBUFFER_BINDING, 1);
  ints("read framebuffer", GL_READ_FRAMEBUFFER_BINDING, 1);
  ints("renderbuffer", GL_RENDERBUFFER_BINDING, 1);
  ints("program", GL_CURRENT_PROGRAM, 1);
  ints("vertex array", GL_VERTEX_ARRAY_BINDING, 1);
  ints("array buffer", GL_ARRAY_BUFFER_BINDING, 1);
  ints("pixel pack buffer", GL_PIXEL_PACK_BUFFER_BINDING, 1);
  ints("pixel unpack buffer", GL_PIXEL_UNPACK_BUFFER_BINDING, 1);
  ints("active texture", GL_ACTIVE_TEXTURE, 1);
  GLint active = 0;
  g.GetIntegerv(GL_ACTIVE_TEXTURE, &active);
  for (int unit = 0; unit < kUnits; ++unit) {
    g.ActiveTexture(GLenum(GL_TEXTURE0 + unit));
    const std::string u = " unit " + std::to_string(unit);
    ints("2D texture" + u, GL_TEXTURE_BINDING_2D, 1);
    ints("2D-array texture" + u, GL_TEXTURE_BINDING_2D_ARRAY, 1);
    ints("2D-multisample texture" + u, GL_TEXTURE_BINDING_2D_MULTISAMPLE, 1);
    ints("sampler" + u, GL_SAMPLER_BINDING, 1);
  }
  g.ActiveTexture(GLenum(active));
  ints("viewport", GL_VIEWPORT, 4);
  ints("scissor box", GL_SCISSOR_BOX, 4);
  enabled("scissor test", GL_SCISSOR_TEST);
  enabled("depth test", GL_DEPTH_TEST);
  ints("depth func", GL_DEPTH_FUNC, 1);
  GLboolean mask[4] = {};
  g.GetBooleanv(GL_DEPTH_WRITEMASK, mask);
  out.push_back({"depth write mask", {double(mask[0])}});
  GLdouble clearDepth = 0.0;
  g.GetDoublev(GL_DEPTH_CLEAR_VALUE, &clearDepth);
  out.push_back({"clear depth", {clearDepth}});
  enabled("cull face", GL_CULL_FACE);
  ints("cull face mode", GL_CULL_FACE_MODE, 1);
  ints("front face", GL_FRONT_FACE, 1);
  ints("polygon mode", GL_POLYGON_MODE, 1);
  enabled("blend", GL_BLEND);
  ints("blend src rgb", GL_BLEND_SRC_RGB, 1);
  ints("blend dst rgb", GL_BLEND_DST_RGB, 1);
  ints("blend src alpha", GL_BLEND_SRC_ALPHA, 1);
  ints("blend dst alpha", GL_BLEND_DST_ALPHA, 1);
  ints("blend equation rgb", GL_BLEND_EQUATION_RGB, 1);
  ints("blend equation alpha", GL_BLEND_EQUATION_ALPHA, 1);
  g.GetBooleanv(GL_COLOR_WRITEMASK, mask);
  out.push_back({"colour write mask", {double(mask[0]), double(mask[1]), double(mask[2]), double(mask[3])}});
  GLfloat clear[4] = {};
  g.GetFloatv(GL_COLOR_CLEAR_VALUE, clear);
  out.push_back({"clear colour", {clear[0], clear[1], clear[2], clear[3]}});
  enabled("framebuffer sRGB", GL_FRAMEBUFFER_SRGB);
  enabled("multisample", GL_MULTISAMPLE);
  enabled("stencil test", GL_STENCIL_TEST);
  enabled("polygon offset fill", GL_POLYGON_OFFSET_FILL);
  enabled("sample alpha to coverage", GL_SAMPLE_ALPHA_TO_COVERAGE);
  enabled("sample coverage", GL_SAMPLE_COVERAGE);
  enabled("rasterizer discard", GL_RASTERIZER_DISCARD);
  enabled("primitive restart", GL_PRIMITIVE_RESTART);
  enabled("colour logic op", GL_COLOR_LOGIC_OP);
  for (int i = 0; i < 6; ++i)
    enabled("clip distance " + std::to_string(i), GLenum(GL_CLIP_DISTANCE0 + i));
  ints("pack alignment", GL_PACK_ALIGNMENT, 1);
  ints("unpack alignment", GL_UNPACK_ALIGNMENT, 1);
  ints("unpack row length", GL_UNPACK_ROW_LENGTH, 1);
  ints("unpack skip pixels", GL_UNPACK_SKIP_PIXELS, 1);
  ints("unpack skip rows", GL_UNPACK_SKIP_ROWS, 1);
  return out;
}

// The host's own objects that the hostile state names.
struct HostObjects {
  GLuint framebuffers[2] = {0, 0}, renderbuffer = 0, buffers[3] = {0, 0, 0}, samplers[kUnits] = {};
  GLuint textures2d[kUnits] = {}, texturesArray[kUnits] = {}, texturesMs[kUnits] = {};
};

HostObjects createHostObjects(const gl::GlApi& g) {
  HostObjects h;
  g.GenFramebuffers(2, h.framebuffers);
  g.GenRenderbuffers(1, &h.renderbuffer);
  g.GenBuffers(3, h.buffers);
  g.BindBuffer(GL_PIXEL_UNPACK_BUFFER, h.buffers[1]);
  g.BufferData(GL_PIXEL_UNPACK_BUFFER, 16, nullptr, GL_STATIC_DRAW);  // far too small for any upload
  g.BindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  g.GenSamplers(kUnits, h.samplers);
  g.GenTextures(kUnits, h.textures2d);
  g.GenTextures(kUnits, h.texturesArray);
  g.GenTextures(kUnits, h.texturesMs);
  for (int i = 0; i < kUnits; ++i) {
    // A sampler that would break the renderer's lookups: mip-mapped minification, comparison.
    g.SamplerParameteri(h.samplers[i], GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    g.SamplerParameteri(h.samplers[i], GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    g.SamplerParameteri(h.samplers[i], GL_TEXTURE_WRAP_S, GL_MIRRORED_REPEAT);
  }
  return h;
}

// Sets every listed state to a value other than GL's default (the host's framebuffer `fbo` as
// the draw framebuffer, another as the read one).
void setHostileState(const gl::GlApi& g, const HostObjects& h, const HostDrawer& drawer, GLuint fbo) {
  g.BindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo);
  g.BindFramebuffer(GL_READ_FRAMEBUFFER, h.framebuffers[0]);
  g.BindRenderbuffer(GL_RENDERBUFFER, h.renderbuffer);
  g.UseProgram(drawer.program());
  g.BindVertexArray(drawer.vertexArray());
  g.BindBuffer(GL_ARRAY_BUFFER, h.buffers[0]);
  g.BindBuffer(GL_PIXEL_UNPACK_BUFFER, h.buffers[1]);
  g.BindBuffer(GL_PIXEL_PACK_BUFFER, h.buffers[2]);
  for (int unit = 0; unit < kUnits; ++unit) {
    g.ActiveTexture(GLenum(GL_TEXTURE0 + unit));
    g.BindTexture(GL_TEXTURE_2D, h.textures2d[unit]);
    g.BindTexture(GL_TEXTURE_2D_ARRAY, h.texturesArray[unit]);
    g.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, h.texturesMs[unit]);
    g.BindSampler(GLuint(unit), h.samplers[unit]);
  }
  g.ActiveTexture(GL_TEXTURE5);
  g.Viewport(3, 4, 50, 60);
  g.Scissor(1, 2, 30, 40);
  g.Enable(GL_SCISSOR_TEST);
  g.Enable(GL_DEPTH_TEST);
  g.DepthFunc(GL_GREATER);
  g.DepthMask(GL_FALSE);
  g.ClearDepth(0.25);
  g.Enable(GL_CULL_FACE);
  g.CullFace(GL_FRONT_AND_BACK);
  g.FrontFace(GL_CW);
  g.PolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  g.Enable(GL_BLEND);
  g.BlendFuncSeparate(GL_SRC_COLOR, GL_DST_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_CONSTANT_COLOR);
  g.BlendEquationSeparate(GL_FUNC_SUBTRACT, GL_MAX);
  g.ColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
  g.ClearColor(0.1f, 0.2f, 0.3f, 0.4f);
  g.Enable(GL_FRAMEBUFFER_SRGB);
  g.Disable(GL_MULTISAMPLE);
  g.Enable(GL_STENCIL_TEST);
  g.StencilFunc(GL_NEVER, 0, 0xff);
  g.Enable(GL_POLYGON_OFFSET_FILL);
  g.PolygonOffset(4.0f, 64.0f);
  g.Enable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  g.Enable(GL_SAMPLE_COVERAGE);
  g.SampleCoverage(0.0f, GL_FALSE);
  g.Enable(GL_RASTERIZER_DISCARD);
  g.Enable(GL_PRIMITIVE_RESTART);
  g.PrimitiveRestartIndex(0);
  g.Enable(GL_COLOR_LOGIC_OP);
  g.LogicOp(GL_INVERT);
  for (int i = 0; i < 6; ++i)
    g.Enable(GLenum(GL_CLIP_DISTANCE0 + i));
  g.PixelStorei(GL_PACK_ALIGNMENT, 1);
  g.PixelStorei(GL_UNPACK_ALIGNMENT, 2);
  g.PixelStorei(GL_UNPACK_ROW_LENGTH, 7);
  g.PixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
  g.PixelStorei(GL_UNPACK_SKIP_ROWS, 5);
}

// GL's defaults for what setHostileState changes (so that the host's own drawing below works).
void setDefaultState(const gl::GlApi& g) {
  g.BindFramebuffer(GL_FRAMEBUFFER, 0);
  g.BindRenderbuffer(GL_RENDERBUFFER, 0);
  g.UseProgram(0);
  g.BindVertexArray(0);
  g.BindBuffer(GL_ARRAY_BUFFER, 0);
  g.BindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  g.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  for (int unit = 0; unit < kUnits; ++unit) {
    g.ActiveTexture(GLenum(GL_TEXTURE0 + unit));
    g.BindTexture(GL_TEXTURE_2D, 0);
    g.BindTexture(GL_TEXTURE_2D_ARRAY, 0);
    g.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
    g.BindSampler(GLuint(unit), 0);
  }
  g.ActiveTexture(GL_TEXTURE0);
  g.Viewport(0, 0, kWidth, kHeight);
  g.Scissor(0, 0, kWidth, kHeight);
  g.Disable(GL_SCISSOR_TEST);
  g.Disable(GL_DEPTH_TEST);
  g.DepthFunc(GL_LESS);
  g.DepthMask(GL_TRUE);
  g.ClearDepth(1.0);
  g.Disable(GL_CULL_FACE);
  g.CullFace(GL_BACK);
  g.FrontFace(GL_CCW);
  g.PolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  g.Disable(GL_BLEND);
  g.BlendFuncSeparate(GL_ONE, GL_ZERO, GL_ONE, GL_ZERO);
  g.BlendEquationSeparate(GL_FUNC_ADD, GL_FUNC_ADD);
  g.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  g.ClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  g.Disable(GL_FRAMEBUFFER_SRGB);
  g.Enable(GL_MULTISAMPLE);
  for (const GLenum cap :
       {GL_STENCIL_TEST, GL_POLYGON_OFFSET_FILL, GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_COVERAGE,
        GL_RASTERIZER_DISCARD, GL_PRIMITIVE_RESTART, GL_COLOR_LOGIC_OP})
    g.Disable(cap);
  for (int i = 0; i < 6; ++i)
    g.Disable(GLenum(GL_CLIP_DISTANCE0 + i));
  g.PixelStorei(GL_PACK_ALIGNMENT, 4);
  g.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
  g.PixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  g.PixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  g.PixelStorei(GL_UNPACK_SKIP_ROWS, 0);
}

TEST(StateContractTest, RenderToRestoresEveryListedStateForEveryMethodAndDepthMode) {
  auto contextResult = createContext(Backend::Egl);
  ASSERT_TRUE(contextResult) << "no EGL context: " << contextResult.error().message;
  auto& context = *contextResult;
  auto loaded = gl::loadGl(context->procAddressFunction());
  ASSERT_TRUE(loaded) << loaded.error().message;
  const gl::GlApi& g = **loaded;
  // The host framebuffer: RGBA8 and depth + stencil (so that the stencil test could bite).
  GLuint fbo = 0, rb[2] = {0, 0};
  g.GenFramebuffers(1, &fbo);
  g.GenRenderbuffers(2, rb);
  g.BindRenderbuffer(GL_RENDERBUFFER, rb[0]);
  g.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, kWidth, kHeight);
  g.BindRenderbuffer(GL_RENDERBUFFER, rb[1]);
  g.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, kWidth, kHeight);
  g.BindFramebuffer(GL_FRAMEBUFFER, fbo);
  g.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
  g.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
  ASSERT_EQ(g.CheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  const HostObjects host = createHostObjects(g);
  HostDrawer drawer(g);
  ASSERT_TRUE(drawer.ok());

  for (const int samples : {0, 4}) {
    render::RendererSettings settings;
    settings.samples = samples;
    settings.shadowMapSize = 256;
    auto renderer = render::Renderer::create(context->procAddressFunction(), settings);
    ASSERT_TRUE(renderer) << renderer.error().message;
    auto textures = uploadMethodTextures(*renderer);
    ASSERT_TRUE(textures) << textures.error().message;
    const PlanarSphere sphere = makePlanarSphere(14.0f, 16, 32);
    auto mesh = renderer->createMesh(sphere.arrays());
    ASSERT_TRUE(mesh);
    // One sphere per method in a row, a shadow-casting light.
    render::Scene scene = goldenScene();
    scene.lights[0].castsShadows = true;
    float x = -64.0f;
    for (const render::ShadingMethod m : kAllMethods) {
      render::SceneObject o = methodObject(m, *mesh, *textures, 1.0f / (2.0f * 3.14159265f * 14.0f));
      o.model[12] = x;  // translation
      x += 32.0f;
      scene.objects.push_back(o);
    }
    for (const render::HostDepth depth : {render::HostDepth::TestAndWrite, render::HostDepth::Ignore}) {
      SCOPED_TRACE(std::string(samples > 1 ? "MSAA " : "single-sample ") +
                   (depth == render::HostDepth::TestAndWrite ? "TestAndWrite" : "Ignore"));
      const render::HostFramebuffer target{fbo, 0, 0, kWidth, kHeight, true, depth};
      // Step 1: the image with GL's default state, as the reference.
      const auto frame = [&](bool hostile) -> Result<Image8> {
        setDefaultState(g);
        g.BindFramebuffer(GL_FRAMEBUFFER, fbo);
        g.Viewport(0, 0, kWidth, kHeight);
        g.ClearColor(0.0f, 0.0f, 1.0f, 1.0f);
        g.ClearDepth(1.0);
        g.ClearStencil(0);
        g.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        g.ClearColor(0.0f, 0.0f, 0.0f, 0.0f);
        if (hostile) setHostileState(g, host, drawer, fbo);
        const std::vector<Entry> before = snapshot(g);
        if (auto r = renderer->renderTo(scene, target); !r) return r.error();
        const std::vector<Entry> after = snapshot(g);
        EXPECT_EQ(before.size(), after.size());
        for (std::size_t i = 0; i < before.size() && i < after.size(); ++i)
          EXPECT_EQ(after[i].values, before[i].values) << before[i].name << " changed";
        if (auto r = gl::checkGlError(g, "after renderTo"); !r) return r.error();
        setDefaultState(g);
        Image8 image(kWidth, kHeight, 4);
        g.BindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
        g.ReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
        return image;
      };
      auto reference = frame(false);
      ASSERT_TRUE(reference) << reference.error().message;
      // Step 2: every listed state differs from GL's default...
      setDefaultState(g);
      const std::vector<Entry> defaults = snapshot(g);
      setHostileState(g, host, drawer, fbo);
      const std::vector<Entry> hostile = snapshot(g);
      ASSERT_EQ(defaults.size(), hostile.size());
      for (std::size_t i = 0; i < defaults.size(); ++i)
        EXPECT_NE(defaults[i].values, hostile[i].values)
            << defaults[i].name << " is not set to a non-default value";
      // ...and comes back unchanged, and the image is the same as with the defaults.
      auto image = frame(true);
      ASSERT_TRUE(image) << image.error().message;
      for (const char* pass : {"shadow:0", "lit", "separable:geometry", "texture-space:final", "ray-march",
                               "parallax:geometry", "tonemap"})
        EXPECT_NE(renderer->lastTimings().find(pass), nullptr) << pass;
      EXPECT_EQ(renderer->lastTimings().find("host-depth") != nullptr,
                depth == render::HostDepth::TestAndWrite);
      int covered = 0;
      for (std::size_t i = 0; i < reference->pixels.size(); i += 4)
        covered += reference->pixels[i + 2] < 200;  // not the host's blue
      EXPECT_GT(covered, 1500) << "the five spheres are drawn";
      const ImageDiff d = compareImages(*image, *reference, 0);
      EXPECT_EQ(d.maxDiff, 0) << "the host's state changed the image (" << d.fractionOver * 100.0
                              << " % of pixels)";
    }
  }
  setDefaultState(g);
  g.DeleteFramebuffers(1, &fbo);
  g.DeleteRenderbuffers(2, rb);
}

}  // namespace
}  // namespace tissue::test
