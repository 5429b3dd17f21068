// The scene's side of the quality controller without GL: an organ's projected footprint,
// distance and view angle, and the atlas's setting names as method choices.
#include <gtest/gtest.h>

#include "tissue/scene/budget.h"

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

}  // namespace
}  // namespace tissue::scene
