// Per-object model matrices (issue 12, embedding): an object drawn with a model matrix must look
// like its mesh pre-transformed on the CPU (positions by M, normals by the normal matrix,
// tangents by M3, local planes mapped onto their images), for every shading method, with a
// shadow-casting light (the shadow fit uses the transformed bounds) and a Lit ground patch
// receiving the shadow. Bad matrices are one clear error.
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>

#include "embedding_scene.h"
#include "gl_test_support.h"
#include "image_compare.h"

namespace tissue::test {
namespace {

constexpr int kSize = 128;
constexpr float kRadius = 25.0f;  // mm, the object-space sphere

Mat4 toArray(const glm::mat4& m) {
  Mat4 out;
  std::memcpy(out.data(), glm::value_ptr(m), sizeof(float) * 16);
  return out;
}

// The sphere as a CPU pre-transform would give it: what the renderer must reproduce.
PlanarSphere preTransformed(const PlanarSphere& s, const glm::mat4& m) {
  PlanarSphere out = s;
  const glm::mat3 m3(m), n3 = glm::transpose(glm::inverse(m3));
  for (std::size_t i = 0; i < s.mesh.positions.size(); ++i) {
    const Float3 p = s.mesh.positions[i], n = s.mesh.normals[i];
    const Float4 t = s.mesh.tangents[i], q = s.planes[i];
    const glm::vec3 wp = glm::vec3(m * glm::vec4(p.x, p.y, p.z, 1.0f));
    const glm::vec3 wn = glm::normalize(n3 * glm::vec3(n.x, n.y, n.z));
    const glm::vec3 wt = glm::normalize(m3 * glm::vec3(t.x, t.y, t.z));
    // The plane through P + d N with normal N_S, mapped: N_S' by the normal matrix, d' so that
    // P' + d' N' lies on the image plane.
    const glm::vec3 ns = glm::normalize(n3 * glm::vec3(q.x, q.y, q.z));
    const float d = q.w * glm::dot(ns, m3 * glm::vec3(n.x, n.y, n.z)) / glm::dot(ns, wn);
    out.mesh.positions[i] = {wp.x, wp.y, wp.z};
    out.mesh.normals[i] = {wn.x, wn.y, wn.z};
    out.mesh.tangents[i] = {wt.x, wt.y, wt.z, t.w};
    out.planes[i] = {ns.x, ns.y, ns.z, d};
  }
  return out;
}

render::Scene shadowScene() {
  render::Scene scene = goldenScene();
  scene.camera.verticalFovDeg = 55.0f;
  scene.lights[0].castsShadows = true;
  return scene;
}

struct Transform {
  const char* name;
  glm::mat4 model;
  // Shadow maps on. Their frustum is fitted to the world bounds, which the renderer takes as the
  // box around the transformed corners of the mesh's box: as tight as the pre-transformed mesh's
  // box under translation and scale, looser under rotation (a slightly different shadow map:
  // aliasing at the shadow's edge differs).
  bool shadows;
  bool rotated;
};

glm::mat4 rigid() {
  return glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(28.0f, -6.0f, 10.0f)), glm::radians(35.0f),
                     glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f)));
}

class ModelMatrixTest : public ::testing::TestWithParam<render::ShadingMethod> {};

TEST_P(ModelMatrixTest, MatchesTheMeshPreTransformedOnTheCpu) {
  const render::ShadingMethod method = GetParam();
  auto contextResult = createContext(Backend::Egl);
  ASSERT_TRUE(contextResult) << "no EGL context: " << contextResult.error().message;
  auto& context = *contextResult;
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  auto textures = uploadMethodTextures(*renderer);
  ASSERT_TRUE(textures) << textures.error().message;
  const PlanarSphere sphere = makePlanarSphere(kRadius, 32, 64);
  auto objectMesh = renderer->createMesh(sphere.arrays());
  auto ground = renderer->createMesh(makePatch(90.0f, 4, -45.0f).arrays());
  ASSERT_TRUE(objectMesh && ground);
  render::SceneObject groundObject;
  groundObject.mesh = *ground;

  const glm::mat4 far =
      glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(36.0f, -8.0f, 4.0f)), glm::vec3(1.2f));
  std::vector<Transform> transforms = {
      {"rigid", rigid(), false, true},
      {"rigid+uniform-scale", glm::scale(rigid(), glm::vec3(1.3f)), false, true},
      // Beyond the ground's bounds: the shadow fit must follow the transformed bounds.
      {"shadowed translation+scale", far, true, false},
      {"shadowed rigid+uniform-scale", glm::scale(rigid(), glm::vec3(1.3f)), true, true},
  };
  // Non-uniform scale: exact for the methods whose settings hold no mesh-derived density.
  if (method == render::ShadingMethod::Lit || method == render::ShadingMethod::Separable)
    transforms.push_back({"non-uniform", glm::scale(rigid(), glm::vec3(1.3f, 0.8f, 1.1f)), false, true});
  for (const Transform& t : transforms) {
    SCOPED_TRACE(t.name);
    const float scale = std::cbrt(glm::determinant(glm::mat3(t.model)));
    const float uvPerMm = 1.0f / (2.0f * 3.14159265f * kRadius * scale);  // world mm (scene.h)
    render::Scene scene = shadowScene();
    scene.lights[0].castsShadows = t.shadows;
    // A: the object-space mesh through the model matrix.
    render::SceneObject a = methodObject(method, *objectMesh, *textures, uvPerMm);
    a.model = toArray(t.model);
    scene.objects = {groundObject, a};
    auto withModel = renderer->renderImage(scene, kSize, kSize);
    ASSERT_TRUE(withModel) << withModel.error().message;
    // B: the same mesh transformed on the CPU, identity model.
    const PlanarSphere moved = preTransformed(sphere, t.model);
    auto movedMesh = renderer->createMesh(moved.arrays());
    ASSERT_TRUE(movedMesh);
    scene.objects = {groundObject, methodObject(method, *movedMesh, *textures, uvPerMm)};
    auto preMoved = renderer->renderImage(scene, kSize, kSize);
    ASSERT_TRUE(preMoved) << preMoved.error().message;
    // C: the untransformed mesh, to show that the transform changes the image a lot.
    scene.objects = {groundObject, methodObject(method, *objectMesh, *textures, uvPerMm)};
    auto unmoved = renderer->renderImage(scene, kSize, kSize);
    ASSERT_TRUE(unmoved);
    renderer->destroyMesh(*movedMesh);

    const ImageDiff same = compareImages(*withModel, *preMoved, 4);
    const ImageDiff moved2 = compareImages(*withModel, *unmoved, 4);
    std::printf("[ model ] %s %s: vs pre-transformed max %d mean %.4f over-4 %.4f; vs unmoved mean %.2f\n",
                std::string(render::shadingMethodName(method)).c_str(), t.name, same.maxDiff, same.meanDiff,
                same.fractionOver, moved2.meanDiff);
    // Texture space sizes its map from the nearest corner of the world box (Jimenez eq. 3) and
    // measures d_ref from the UV density at upload (divided by the model's scale): both differ
    // slightly from the pre-transformed mesh's, so its map can be a few texels larger or smaller.
    const bool exact = method != render::ShadingMethod::TextureSpace && !(t.shadows && t.rotated);
    if (exact) {
      EXPECT_LE(same.maxDiff, 2);
    } else {
      EXPECT_LT(same.meanDiff, 0.2);
      EXPECT_LT(same.fractionOver, t.shadows && t.rotated ? 0.01 : 0.003);
    }
    EXPECT_GT(moved2.meanDiff, 4.0) << "the model matrix must move the object";
  }
}

INSTANTIATE_TEST_SUITE_P(Methods, ModelMatrixTest, ::testing::ValuesIn(kAllMethods),
                         [](const auto& p) { return methodTestName(p.param); });

TEST(ModelMatrixErrorTest, MirroredSingularProjectiveAndNonFiniteModelsAreErrors) {
  auto contextResult = createContext(Backend::Egl);
  ASSERT_TRUE(contextResult) << "no EGL context: " << contextResult.error().message;
  auto& context = *contextResult;
  auto renderer = render::Renderer::create(context->procAddressFunction());
  ASSERT_TRUE(renderer) << renderer.error().message;
  auto mesh = renderer->createMesh(makeSphere(kRadius, 12, 24).arrays());
  ASSERT_TRUE(mesh);
  render::Scene scene = shadowScene();
  render::SceneObject o;
  o.mesh = *mesh;
  scene.objects = {o};
  ASSERT_TRUE(renderer->renderImage(scene, 32, 32));
  const auto expectError = [&](const glm::mat4& m, const char* what) {
    scene.objects[0].model = toArray(m);
    auto r = renderer->renderImage(scene, 32, 32);
    ASSERT_FALSE(r) << what;
    EXPECT_NE(r.error().message.find(what), std::string::npos) << r.error().message;
  };
  expectError(glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f)), "determinant");  // mirrored
  expectError(glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, 0.0f, 1.0f)), "determinant");   // singular
  glm::mat4 projective(1.0f);
  projective[0][3] = 0.1f;
  expectError(projective, "affine");
  glm::mat4 nan(1.0f);
  nan[3][0] = std::numeric_limits<float>::quiet_NaN();
  expectError(nan, "non-finite");
  // A small regular scale (metres to millimetres the other way round) is fine.
  scene.objects[0].model = toArray(glm::scale(glm::mat4(1.0f), glm::vec3(1e-3f)));
  EXPECT_TRUE(renderer->renderImage(scene, 32, 32));
}

}  // namespace
}  // namespace tissue::test
