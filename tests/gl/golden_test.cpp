// Golden images: the procedural normal-mapped sphere through EGL and through OSMesa.
#include "gl_test_support.h"
#include "image_compare.h"
#include "test_scene.h"

namespace tissue::test {
namespace {

class GoldenTest : public ::testing::TestWithParam<Backend> {};

TEST_P(GoldenTest, NormalMappedSphereMatchesGolden) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  const SphereMesh sphere = makeSphere(40.0f, 48, 96);
  ASSERT_TRUE(renderer->setMesh(sphere.arrays()));
  ASSERT_TRUE(renderer->setBaseColor(makeBaseColor(256)));
  ASSERT_TRUE(renderer->setNormalMap(makeBumpyNormalMap(256)));
  auto image = renderer->renderImage(goldenScene(), 256, 256);
  ASSERT_TRUE(image) << image.error().message;
  const std::string failure =
      checkGolden(std::string("normal_mapped_sphere_") + backendName(GetParam()), *image);
  EXPECT_TRUE(failure.empty()) << failure;
  const auto& t = renderer->lastTimings();
  for (const auto& pass : t.passes)
    std::printf("[ timing ] %s 256x256 %s: %.3f ms CPU / %.3f ms GPU\n", backendName(GetParam()),
                pass.name.c_str(), pass.cpuMs, pass.gpuMs);
}

INSTANTIATE_TEST_SUITE_P(Backends, GoldenTest, ::testing::Values(Backend::Egl, Backend::OsMesa),
                         backendParamName);

TEST(GoldenCompareTest, ToleranceCatchesARealChange) {
  Image8 a(16, 16, 4), b(16, 16, 4);
  EXPECT_EQ(compareImages(a, b, 3).fractionOver, 0.0);
  b.at(3, 3)[1] = 4;  // one pixel, just over the tolerance
  const ImageDiff d = compareImages(a, b, 3);
  EXPECT_EQ(d.maxDiff, 4);
  EXPECT_DOUBLE_EQ(d.fractionOver, 1.0 / 256.0);
}

}  // namespace
}  // namespace tissue::test
