// Renderer behaviour: the normal map and the tangent handedness change the image, deformation
// updates, host framebuffers (state restored), two renderers, errors instead of aborts.
#include "gl_test_support.h"
#include "image_compare.h"
#include "test_scene.h"
#include "tissue/gl/gl_api.h"
#include "tissue/gl/objects.h"

namespace tissue::test {
namespace {

constexpr int kSize = 128;

class RenderTest : public ::testing::TestWithParam<Backend> {};

Result<Image8> renderSphere(render::Renderer& renderer, const SphereMesh& sphere, const Image8& normalMap) {
  if (auto r = renderer.setMesh(sphere.arrays()); !r) return r.error();
  if (auto r = renderer.setNormalMap(normalMap); !r) return r.error();
  return renderer.renderImage(goldenScene(), kSize, kSize);
}

TEST_P(RenderTest, NormalMapAndHandednessChangeTheImage) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  SphereMesh sphere = makeSphere(40.0f, 32, 64);
  auto flat = renderSphere(*renderer, sphere, makeFlatNormalMap(128));
  auto bumpy = renderSphere(*renderer, sphere, makeBumpyNormalMap(128));
  for (auto& t : sphere.tangents)
    t.w = -t.w;
  auto flipped = renderSphere(*renderer, sphere, makeBumpyNormalMap(128));
  ASSERT_TRUE(flat && bumpy && flipped);
  renderer->setNormalMapping(false);
  auto vertexNormals = renderer->renderImage(goldenScene(), kSize, kSize);
  ASSERT_TRUE(vertexNormals);
  // A flat normal map shades like the vertex normals (up to 8-bit quantisation of the map).
  EXPECT_LT(meanDifference(*flat, *vertexNormals), 0.5);
  EXPECT_GT(meanDifference(*flat, *bumpy), 2.0);
  EXPECT_GT(meanDifference(*bumpy, *flipped), 1.0);
  // The sphere is in the picture: the centre is lit tissue, the corner background.
  EXPECT_GT(bumpy->at(kSize / 2, kSize / 2)[0], 60);
  EXPECT_LT(bumpy->at(0, 0)[0], 40);
}

TEST_P(RenderTest, UpdateMeshMovesTheSurface) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  SphereMesh sphere = makeSphere(40.0f, 24, 48);
  ASSERT_TRUE(renderer->setMesh(sphere.arrays()));
  auto before = renderer->renderImage(goldenScene(), kSize, kSize);
  for (auto& p : sphere.positions)
    p.x += 25.0f;  // mm, shift right
  ASSERT_TRUE(renderer->updateMesh(sphere.positions, sphere.normals, sphere.tangents));
  auto after = renderer->renderImage(goldenScene(), kSize, kSize);
  ASSERT_TRUE(before && after);
  EXPECT_GT(meanDifference(*before, *after), 5.0);
  EXPECT_LT(after->at(kSize / 8, kSize / 2)[0], 40);  // the left edge is background now
  // A size mismatch is an Error, not a crash.
  sphere.positions.pop_back();
  EXPECT_FALSE(renderer->updateMesh(sphere.positions, sphere.normals, sphere.tangents));
}

TEST_P(RenderTest, DrawsIntoHostFramebufferAndRestoresHostState) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto loaded = gl::loadGl(context->procAddressFunction());
  ASSERT_TRUE(loaded);
  const gl::GlApi& g = **loaded;
  // The host's framebuffer: an RGBA8 texture and a depth renderbuffer.
  GLuint hostFbo = 0, hostColor = 0, hostDepth = 0;
  g.GenFramebuffers(1, &hostFbo);
  g.GenTextures(1, &hostColor);
  g.GenRenderbuffers(1, &hostDepth);
  g.BindTexture(GL_TEXTURE_2D, hostColor);
  g.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kSize, kSize, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  g.BindRenderbuffer(GL_RENDERBUFFER, hostDepth);
  g.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, kSize, kSize);
  g.BindFramebuffer(GL_FRAMEBUFFER, hostFbo);
  g.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, hostColor, 0);
  g.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, hostDepth);
  ASSERT_EQ(g.CheckFramebufferStatus(GL_FRAMEBUFFER), static_cast<GLenum>(GL_FRAMEBUFFER_COMPLETE));
  {
    // Adopting the host's name and dropping the wrapper leaves the name alive.
    gl::Framebuffer adopted = gl::Framebuffer::wrap(g, hostFbo);
    EXPECT_FALSE(adopted.owned());
  }
  EXPECT_TRUE(g.IsFramebuffer(hostFbo));
  g.ClearColor(0.0f, 0.0f, 1.0f, 1.0f);
  g.Clear(GL_COLOR_BUFFER_BIT);
  // Host state the renderer must leave alone: another binding, viewport, blend, clear colour.
  GLuint otherFbo = 0;
  g.GenFramebuffers(1, &otherFbo);
  g.BindFramebuffer(GL_FRAMEBUFFER, otherFbo);
  g.Viewport(3, 4, 50, 60);
  g.Enable(GL_BLEND);
  g.ClearColor(0.1f, 0.2f, 0.3f, 0.4f);

  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  const SphereMesh sphere = makeSphere(40.0f, 24, 48);
  ASSERT_TRUE(renderer->setMesh(sphere.arrays()));
  ASSERT_TRUE(renderer->renderTo(
      goldenScene(),
      {.framebuffer = hostFbo, .x = 0, .y = 0, .width = kSize / 2, .height = kSize, .clear = true}));

  GLint binding = 0, viewport[4] = {};
  GLfloat clear[4] = {};
  g.GetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &binding);
  g.GetIntegerv(GL_VIEWPORT, viewport);
  g.GetFloatv(GL_COLOR_CLEAR_VALUE, clear);
  EXPECT_EQ(static_cast<GLuint>(binding), otherFbo);
  EXPECT_EQ(viewport[0], 3);
  EXPECT_EQ(viewport[1], 4);
  EXPECT_EQ(viewport[2], 50);
  EXPECT_EQ(viewport[3], 60);
  EXPECT_TRUE(g.IsEnabled(GL_BLEND));
  EXPECT_FLOAT_EQ(clear[2], 0.3f);
  EXPECT_TRUE(gl::checkGlError(g, "after renderTo"));

  // The left half (the viewport) holds the sphere; the right half keeps the host's blue.
  Image8 pixels(kSize, kSize, 4);
  g.BindFramebuffer(GL_READ_FRAMEBUFFER, hostFbo);
  g.ReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, pixels.pixels.data());
  const std::uint8_t* sphereCentre = pixels.at(kSize / 4, kSize / 2);
  const std::uint8_t* right = pixels.at(3 * kSize / 4, kSize / 2);
  EXPECT_GT(sphereCentre[0], 60);
  EXPECT_EQ(right[0], 0);
  EXPECT_EQ(right[2], 255);
  g.DeleteFramebuffers(1, &otherFbo);
  g.DeleteFramebuffers(1, &hostFbo);
  g.DeleteTextures(1, &hostColor);
  g.DeleteRenderbuffers(1, &hostDepth);
}

TEST_P(RenderTest, TwoRenderersInOneContextAreIndependent) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto a = render::Renderer::create(context->procAddressFunction());
  auto b = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(a && b);
  const SphereMesh big = makeSphere(40.0f, 24, 48), small = makeSphere(15.0f, 24, 48);
  ASSERT_TRUE(a->setMesh(big.arrays()));
  ASSERT_TRUE(b->setMesh(small.arrays()));
  auto imageA = a->renderImage(goldenScene(), kSize, kSize);
  auto imageB = b->renderImage(goldenScene(), kSize, kSize);
  auto imageA2 = a->renderImage(goldenScene(), kSize, kSize);
  ASSERT_TRUE(imageA && imageB && imageA2);
  EXPECT_GT(meanDifference(*imageA, *imageB), 5.0);
  EXPECT_EQ(meanDifference(*imageA, *imageA2), 0.0);
}

TEST_P(RenderTest, ErrorsInsteadOfAborts) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer);
  EXPECT_FALSE(renderer->renderImage(goldenScene(), kSize, kSize));  // no mesh yet
  SphereMesh sphere = makeSphere(10.0f, 8, 16);
  sphere.uvs.pop_back();
  EXPECT_FALSE(renderer->setMesh(sphere.arrays()));
  EXPECT_FALSE(renderer->renderImage(goldenScene(), 0, kSize));
  EXPECT_FALSE(renderer->setBaseColor(Image8{}));
}

TEST_P(RenderTest, MultisamplingSmoothsEdges) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto plain = render::Renderer::create(context->procAddressFunction());
  auto msaa = render::Renderer::create(context->procAddressFunction(),
                                       {.shaders = {}, .samples = 4, .gpuTimers = true});
  ASSERT_TRUE(plain && msaa);
  const SphereMesh sphere = makeSphere(40.0f, 24, 48);
  ASSERT_TRUE(plain->setMesh(sphere.arrays()) && msaa->setMesh(sphere.arrays()));
  auto a = plain->renderImage(goldenScene(), kSize, kSize);
  auto b = msaa->renderImage(goldenScene(), kSize, kSize);
  ASSERT_TRUE(a && b) << (a ? b.error().message : a.error().message);
  const double d = meanDifference(*a, *b);
  EXPECT_GT(d, 0.0);  // edges differ
  EXPECT_LT(d, 3.0);  // the interior does not
}

INSTANTIATE_TEST_SUITE_P(Backends, RenderTest, ::testing::Values(Backend::Egl, Backend::OsMesa),
                         backendParamName);

}  // namespace
}  // namespace tissue::test
