// The scene's side of the quality controller without GL: an organ's projected footprint,
// distance and view angle, and the atlas's setting names as method choices.
#include <gtest/gtest.h>

#include <cmath>

#include "tissue/scene/budget.h"
#include "tissue/scene/organ_methods.h"

namespace tissue::scene {
namespace {

Bounds3 slab() {  // 100 x 60 x 10 mm, thinnest along z
  Bounds3 b;
  b.add(Float3{-50.0f, -30.0f, -5.0f});
  b.add(Float3{50.0f, 30.0f, 5.0f});
  return b;
}

Mat4 translation(Float3 t) {
  Mat4 m = kIdentity4;
  m[12] = t.x, m[13] = t.y, m[14] = t.z;
  return m;
}

TEST(BudgetView, FootprintFallsWithTheSquareOfTheDistanceAndVanishesOffScreen) {
  render::Camera cam;  // at z = 200 looking at the origin
  cam.eye = {0, 0, 0};
  cam.target = {0, 0, -1};
  const auto near = organView(slab(), translation({0, 0, -400}), cam, 320, 240);
  const auto far = organView(slab(), translation({0, 0, -800}), cam, 320, 240);
  EXPECT_GT(near.footprintPx, 100.0);
  EXPECT_LT(near.footprintPx, 320.0 * 240.0);
  EXPECT_NEAR(far.footprintPx / near.footprintPx, 0.25, 0.03);
  EXPECT_NEAR(near.distanceMm, 400.0, 1e-3);
  EXPECT_LT(near.viewAngleDeg, 1.0);  // seen face-on (along its thin axis)
  const auto behind = organView(slab(), translation({0, 0, 800}), cam, 320, 240);
  EXPECT_EQ(behind.footprintPx, 320.0 * 240.0);  // through the near plane: the whole image at most
  const auto aside = organView(slab(), translation({5000, 0, -400}), cam, 320, 240);
  EXPECT_EQ(aside.footprintPx, 0.0);
  // Edge-on: the camera in the slab's plane.
  render::Camera side;
  side.eye = {0, -600, 0};
  side.target = {0, 0, 0};
  side.up = {0, 0, 1};
  EXPECT_GT(organView(slab(), kIdentity4, side, 320, 240).viewAngleDeg, 89.0);
}

// A closed box of `size` mm about the origin, counter-clockwise outside (12 triangles).
SurfaceMesh box(Float3 size) {
  SurfaceMesh m;
  for (int c = 0; c < 8; ++c)
    m.positions.push_back(
        {(c & 1 ? 0.5f : -0.5f) * size.x, (c & 2 ? 0.5f : -0.5f) * size.y, (c & 4 ? 0.5f : -0.5f) * size.z});
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

TEST(BudgetView, TheMeshFootprintIsTheProjectedAreaTheBoundsOverstate) {
  render::Camera cam;
  cam.eye = {0, 0, 0};
  cam.target = {0, 0, -1};
  cam.up = {0, 1, 0};
  cam.verticalFovDeg = 45.0f;
  const SurfaceMesh m = box({100.0f, 60.0f, 10.0f});
  Bounds3 b;
  for (const Float3& p : m.positions)
    b.add(p);
  // Face-on at 400 mm: the 100 x 60 mm face, (100 / (2 z tan(22.5) aspect)) x (60 / (2 z tan(22.5)))
  // of the image (the box's depth adds nothing seen face-on but its perspective rim).
  const double tanHalf = std::tan(22.5 * 3.14159265 / 180.0), aspect = 320.0 / 240.0;
  const double face =
      100.0 / (2.0 * 395.0 * tanHalf * aspect) * 60.0 / (2.0 * 395.0 * tanHalf) * 320.0 * 240.0;
  const auto seen = organView(m, b, translation({0, 0, -400}), cam, 320, 240);
  EXPECT_NEAR(seen.footprintPx, face, 0.03 * face);  // the near face at 395 mm
  EXPECT_LE(seen.footprintPx,
            organView(b, translation({0, 0, -400}), cam, 320, 240).footprintPx * 4.0 / 3.14159265 + 1e-6);
  // A box turned 45 degrees about y shows two faces; the bounds' rectangle bounds it, and the
  // angle and distance are the bounds' own.
  const float c = std::cos(0.785398f), s = std::sin(0.785398f);
  Mat4 turned = translation({0, 0, -600});
  turned[0] = c, turned[2] = -s, turned[8] = s, turned[10] = c;
  const auto oblique = organView(m, b, turned, cam, 320, 240);
  const auto bounds = organView(b, turned, cam, 320, 240);
  EXPECT_GT(oblique.footprintPx, 0.0);
  EXPECT_LE(oblique.footprintPx, bounds.footprintPx * 4.0 / 3.14159265 + 1e-6);
  EXPECT_EQ(oblique.distanceMm, bounds.distanceMm);
  EXPECT_EQ(oblique.viewAngleDeg, bounds.viewAngleDeg);
  // Off screen: nothing; an empty mesh: the bounds' estimate (the ellipse).
  EXPECT_EQ(organView(m, b, translation({5000, 0, -400}), cam, 320, 240).footprintPx, 0.0);
  EXPECT_EQ(organView(SurfaceMesh{}, b, translation({0, 0, -400}), cam, 320, 240).footprintPx,
            organView(b, translation({0, 0, -400}), cam, 320, 240).footprintPx);
}

TEST(BudgetView, AtlasSettingNamesBecomeMethodChoices) {
  quality::QualityOption o;
  o.method = "separable";
  o.setting = "jimenez-7";
  auto c = choicesOfSetting(o, {});
  ASSERT_TRUE(c);
  EXPECT_EQ(c->kernel, "jimenez");
  EXPECT_EQ(c->taps, 7);
  o.method = "texture-space";
  o.setting = "2g-plain";
  c = choicesOfSetting(o, {});
  ASSERT_TRUE(c);
  EXPECT_EQ(c->gaussians, 2);
  EXPECT_FALSE(c->cull || c->clip || c->depthSize);
  o.method = "ray-march";
  o.setting = "adaptive-100";
  c = choicesOfSetting(o, {});
  ASSERT_TRUE(c);
  EXPECT_TRUE(c->adaptive);
  EXPECT_EQ(c->samples, 100);
  o.setting = "25";
  c = choicesOfSetting(o, {});
  ASSERT_TRUE(c);
  EXPECT_FALSE(c->adaptive);
  EXPECT_EQ(c->samples, 25);
  o.setting = "many";
  ASSERT_FALSE(choicesOfSetting(o, {}));
}

// A closed cube of side `a` mm: area 6 a^2.
OrganAssets cubeOrgan(float a, MaterialLayer layer) {
  OrganAssets o;
  o.material = defaultMaterial();
  o.material.layers = {layer};
  const float h = 0.5f * a;
  for (int i = 0; i < 8; ++i)
    o.mesh.positions.push_back({i & 1 ? h : -h, i & 2 ? h : -h, i & 4 ? h : -h});
  o.mesh.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                      {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return o;
}

// What the controller learns from a frame: an object's own passes are its; in a pass that draws
// several objects each has its issue time and a share of the rest by weight; a method's passes of
// no object (separable's blurs) are the method's, once.
TEST(BudgetView, FramePassCostsGiveEachObjectItsPassesAndDrawsAndEachMethodItsOwn) {
  const auto pass = [](std::string name, double ms, int object = -1,
                       std::vector<std::pair<int, double>> issued = {}) {
    render::PassTiming p;
    p.name = std::move(name);
    p.cpuMs = ms;
    p.object = object;
    p.issued = std::move(issued);
    return p;
  };
  render::RenderTimings t;
  t.passes = {pass("shadow:0", 9.0),
              pass("lit", 5.5, -1, {{0, 1.0}, {1, 0.5}}),
              pass("separable:geometry", 1.0, -1, {{3, 0.25}}),
              pass("separable:blur-x", 2.0),
              pass("separable:blur-y", 1.5),
              pass("texture-space:irradiance", 7.0, 2),
              pass("texture-space:copy", 0.5),
              pass("tonemap", 3.0)};
  const std::vector<double> weights = {3.0, 1.0, 0.0, 5.0};
  const FramePassCosts c = framePassCosts(t, weights);
  ASSERT_EQ(c.objectMs.size(), 4u);
  EXPECT_DOUBLE_EQ(c.objectMs[0], 1.0 + 4.0 * 0.75);  // the lit pass's rest, 4 ms, by 3 : 1
  EXPECT_DOUBLE_EQ(c.objectMs[1], 0.5 + 4.0 * 0.25);
  EXPECT_DOUBLE_EQ(c.objectMs[2], 7.0);
  EXPECT_DOUBLE_EQ(c.objectMs[3], 1.0);  // alone in its pass: all of it
  ASSERT_EQ(c.methodMs.size(), 5u);
  EXPECT_DOUBLE_EQ(c.methodMs[std::size_t(render::ShadingMethod::Lit)], 0.0);
  EXPECT_DOUBLE_EQ(c.methodMs[std::size_t(render::ShadingMethod::Separable)], 3.5);
  EXPECT_DOUBLE_EQ(c.methodMs[std::size_t(render::ShadingMethod::TextureSpace)], 0.5);
  // The frame's passes (shadows, tone map) are no one's: the overhead.
  double all = 0.0;
  for (double ms : c.objectMs)
    all += ms;
  for (double ms : c.methodMs)
    all += ms;
  EXPECT_DOUBLE_EQ(all, 5.5 + 1.0 + 3.5 + 7.0 + 0.5);
}

TEST(OpticalWrap, IsTheDiffusionLengthOverTheCurvatureRadius) {
  // sigma_tr = sqrt(3 sigma_a (sigma_a + sigma_s (1 - g))) of the band that travels furthest
  // (Jensen et al. 2001), over R = sqrt(area / 4 pi).
  MaterialLayer l;
  l.sigmaS = {8.0f, 9.0f, 10.0f};
  l.sigmaT = {8.1f, 13.0f, 14.0f};
  l.g = 0.9f;
  const double sa = 0.1, sr = 0.8, tr = std::sqrt(3.0 * sa * (sa + sr));  // the red band's
  for (float a : {100.0f, 200.0f}) {
    const double radius = std::sqrt(6.0 * double(a) * double(a) / (4.0 * 3.14159265358979));
    EXPECT_NEAR(double(opticalWrap(cubeOrgan(a, l))), 1.0 / (tr * radius), 0.02 / (tr * radius))
        << a << " mm";
  }
  EXPECT_NEAR(double(opticalWrap(cubeOrgan(100.0f, l)) / opticalWrap(cubeOrgan(200.0f, l))), 2.0, 1e-3);
  EXPECT_EQ(opticalWrap(cubeOrgan(0.5f, l)), 0.5f);  // a tiny organ: clamped to Green's half wrap
}

TEST(SurfaceMaterial, ReflectsWithTheFresnelOfTheMaterialsIndex) {
  // F0 = ((n - 1) / (n + 1))^2 at normal incidence from air, as the truth's boundary reflects.
  OrganAssets o = cubeOrgan(10.0f, {});
  for (float n : {1.33f, 1.4f, 1.5f}) {
    o.material.ior = n;
    const render::Material m = surfaceMaterialOf(o, {0.1f, 0.2f, 0.3f});
    const double f0 = std::pow((double(n) - 1.0) / (double(n) + 1.0), 2.0);
    EXPECT_NEAR(double(m.specular), f0, 1e-6) << "ior " << n;
    EXPECT_EQ(m.ambient.y, 0.2f);  // the artist's fill light passes through as given
  }
}

}  // namespace
}  // namespace tissue::scene
