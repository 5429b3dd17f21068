// The quality controller's properties: the plan fits the budget, more budget never gives a higher
// expected error, the held plan stays under noisy costs, tiny footprints fall back to lit with
// wrap, learned costs converge to the measured ones, and the mesh work follows the method.
#include "tissue/quality/controller.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

namespace tissue::quality {
namespace {

QualityOption option(std::string method, std::string setting, double err, double fixedMs, double msPerPx) {
  QualityOption o;
  o.method = std::move(method);
  o.setting = std::move(setting);
  o.relRms = {err, err * 1.1, err * 1.3, err * 1.2, err * 1.1};
  o.fixedMs = fixedMs;
  o.msPerPx = msPerPx;
  return o;
}

// A table of the atlas's shape: cheap and wrong to dear and right.
QualityTable table() {
  QualityTable t;
  t.options = {option("lit", "default", 0.50, 0.1, 1e-4),
               option("lit", "wrap", 0.48, 0.1, 1.1e-4),
               option("separable", "preintegrated-7", 0.40, 0.8, 3e-4),
               option("separable", "preintegrated-17", 0.35, 1.0, 6e-4),
               option("texture-space", "6g-opt", 0.30, 3.0, 8e-4),
               option("ray-march", "10", 0.20, 1.0, 2e-3),
               option("ray-march", "50", 0.12, 1.0, 8e-3)};
  t.frameOverheadMs = 2.0;
  return t;
}

std::vector<CostModel> priors(const QualityTable& t) {
  std::vector<CostModel> c;
  for (const QualityOption& o : t.options)
    c.push_back(costModelOf(o));
  return c;
}

std::vector<ObjectView> objects() {
  std::vector<ObjectView> v(5);
  v[0].footprintPx = 40000;  // close-up
  v[1].footprintPx = 6000;
  v[1].deforming = true;
  v[2].footprintPx = 3000;
  v[3].footprintPx = 900;
  v[3].viewAngleDeg = 80;
  v[4].footprintPx = 150;  // far and small
  return v;
}

constexpr double kScreenPx = 320.0 * 240.0;

TEST(QualityController, PlanFitsTheBudget) {
  const QualityTable t = table();
  const auto costs = priors(t);
  const auto objs = objects();
  for (double budget : {3.0, 5.0, 8.0, 12.0, 20.0, 50.0, 200.0, 1000.0}) {
    const Plan p = choosePlan(t, costs, t.frameOverheadMs, objs, kScreenPx, budget);
    ASSERT_EQ(p.option.size(), objs.size());
    if (!p.fits) continue;
    EXPECT_LE(p.predictedMs, budget * (1.0 - ControllerSettings{}.headroom) + 1e-9) << budget;
  }
  // Tight budgets cannot be met by anything: the cheapest plan, flagged.
  const Plan none = choosePlan(t, costs, t.frameOverheadMs, objs, kScreenPx, 1.0);
  EXPECT_FALSE(none.fits);
  // A loose one is met, by something better than all-lit.
  const Plan loose = choosePlan(t, costs, t.frameOverheadMs, objs, kScreenPx, 1000.0);
  EXPECT_TRUE(loose.fits);
  EXPECT_LT(loose.expectedError, 0.2);
}

// Nothing fits: the cheapest plan, but between options whose costs are within the headroom of
// each other (one cost measured with noise) the one of lower error, and never one dearer than that.
TEST(QualityController, WhenNothingFitsTheLeastErrorWithinNoiseOfTheCheapestPlan) {
  QualityTable t;
  t.options = {option("lit", "wrap", 0.60, 1.0, 1.0e-4),      // the cheapest by a hair, worse
               option("lit", "default", 0.50, 1.0, 1.02e-4),  // 2 % dearer: within the noise
               option("separable", "svd-7", 0.30, 3.0, 3e-4)};
  ObjectView view;
  view.footprintPx = 5000.0;
  const std::vector<ObjectView> objs(3, view);
  const auto costs = priors(t);
  const Plan p = choosePlan(t, costs, 2.0, objs, kScreenPx, 1.0);  // below the overhead itself
  EXPECT_FALSE(p.fits);
  for (int o : p.option)
    EXPECT_EQ(o, t.find("lit", "default"));
  // The cheapest plan's cost at most x (1 + headroom): separable stays out, though its error is lowest.
  double cheapest = 2.0;
  for (const ObjectView& v : objs)
    cheapest += costs[0].predictMs(v.footprintPx);
  EXPECT_LE(p.predictedMs, cheapest * (1.0 + ControllerSettings{}.headroom) + 1e-9);
  // Twice the per-pixel cost is not noise: the cheap option is kept.
  t.options[1].msPerPx = 2e-4;
  const Plan q = choosePlan(t, priors(t), 2.0, objs, kScreenPx, 1.0);
  for (int o : q.option)
    EXPECT_EQ(o, t.find("lit", "wrap"));
}

TEST(QualityController, MoreBudgetNeverGivesAHigherExpectedError) {
  const QualityTable t = table();
  const auto costs = priors(t);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> px(50.0, 30000.0);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<ObjectView> objs(6);
    for (auto& o : objs)
      o.footprintPx = px(rng);
    double last = 1e30;
    for (double budget = 3.0; budget < 150.0; budget *= 1.13) {
      const Plan p = choosePlan(t, costs, t.frameOverheadMs, objs, kScreenPx, budget);
      if (!p.fits) continue;
      EXPECT_LE(p.expectedError, last + 1e-12) << "trial " << trial << " budget " << budget;
      last = p.expectedError;
    }
    EXPECT_LT(last, 1e30);  // some budget fitted
  }
}

// The fallback threshold of these two tests: the far object's 150 px below it (the default is a
// 4 x 4 px speck, 16 px).
ControllerSettings fallbackAt400Px() {
  ControllerSettings s;
  s.minFootprintPx = 400.0;
  return s;
}

TEST(QualityController, TinyFootprintsFallBackToLitWithWrap) {
  const QualityTable t = table();
  QualityController c(t, fallbackAt400Px());
  const auto& choices = c.update(objects(), kScreenPx, 1000.0);  // budget for anything
  ASSERT_EQ(choices.size(), 5u);
  EXPECT_EQ(choices[4].method, "lit");
  EXPECT_EQ(choices[4].setting, "wrap");
  EXPECT_TRUE(choices[4].fallback);
  // Above the threshold the loose budget buys the best method.
  EXPECT_EQ(choices[0].method, "ray-march");
  EXPECT_EQ(choices[0].setting, "50");
  EXPECT_FALSE(choices[0].fallback);
}

// The fallback tier is lit: with the wrap term where the table says it helps the view, plain
// where the truth shows the wrap term adds error (the budget bench's far organs).
TEST(QualityController, TheFallbackTierTakesTheWrapTermOnlyWhereItHelps) {
  QualityTable t = table();
  const int wrap = t.find("lit", "wrap"), plain = t.find("lit", "default");
  t.options[std::size_t(wrap)].relRms[std::size_t(ViewClass::Rest)] = 0.55;  // above lit's 0.50
  const std::vector<ObjectView> small(1, objects()[4]);                      // 150 px, at rest
  QualityController c(t, fallbackAt400Px());
  const auto& choices = c.update(small, kScreenPx, 1000.0);
  ASSERT_EQ(choices.size(), 1u);
  EXPECT_EQ(choices[0].option, plain);
  EXPECT_TRUE(choices[0].fallback);
  // Grazing, the table's wrap stays below plain lit (0.48 x 1.2 against 0.50 x 1.2): the wrap term.
  std::vector<ObjectView> grazing = small;
  grazing[0].viewAngleDeg = 80.0;
  QualityController g(t, fallbackAt400Px());
  EXPECT_EQ(g.update(grazing, kScreenPx, 1000.0)[0].option, wrap);
  // Never anything but the lit tier below the threshold, however loose the budget (a budget
  // far above every cost coarsens the knapsack's grid instead of growing it).
  for (const ObjectChoice& ch : c.update(small, kScreenPx, 1e9))
    EXPECT_EQ(ch.method, "lit");
}

// The far frame (the low view from farther away) is the footprint axis: an object smaller than
// the low frame's pays the error interpolated in ln px towards the far frame's, one at or below
// the far frame's pays that; a large one the low frame's. The atlas's shape: lit ties the ray
// march at the low frame's 750 px and loses at the far frame's 110.
TEST(QualityController, AnObjectsErrorFollowsItsFootprintFromTheLowFrameToTheFarFrame) {
  QualityTable t;
  QualityOption lit = option("lit", "default", 0.087, 0.1, 1e-4);
  QualityOption march = option("ray-march", "10", 0.088, 0.2, 2e-4);
  const auto low = std::size_t(ViewClass::Low);
  lit.relRms[low] = 0.087, march.relRms[low] = 0.088;
  lit.farRelRms = 0.12, march.farRelRms = 0.097;
  t.options = {lit, march};
  t.framePx[low] = 750.0;
  t.farFramePx = 110.0;
  ControllerSettings s;
  s.errorConfidence = 0.0;
  ObjectView v;
  v.viewAngleDeg = 62.0;
  const auto err = [&](int o, double px) {
    v.footprintPx = px;
    return expectedSquaredError(t, o, v, ViewClass::Low, s);
  };
  // At and above the low frame's pixels, the low frame's errors: lit ahead.
  EXPECT_NEAR(err(0, 750.0), 0.087 * 0.087, 1e-12);
  EXPECT_NEAR(err(0, 5000.0), 0.087 * 0.087, 1e-12);
  EXPECT_LT(err(0, 1000.0), err(1, 1000.0));
  // At and below the far frame's, the far frame's: the ray march ahead.
  EXPECT_NEAR(err(0, 110.0), 0.12 * 0.12, 1e-12);
  EXPECT_NEAR(err(1, 40.0), 0.097 * 0.097, 1e-12);
  EXPECT_LT(err(1, 40.0), err(0, 40.0));
  // Between, linear in ln px.
  const double f = std::log(300.0 / 110.0) / std::log(750.0 / 110.0);
  EXPECT_NEAR(err(0, 300.0), 0.12 * 0.12 + f * (0.087 * 0.087 - 0.12 * 0.12), 1e-12);
  // The plan follows: a 40 px object (above the 16 px fallback) on the ray march, a 1000 px one on lit.
  std::vector<ObjectView> two(2, v);
  two[0].footprintPx = 40.0, two[1].footprintPx = 1000.0;
  const Plan p = choosePlan(t, priors(t), 0.0, two, kScreenPx, 100.0, s);
  EXPECT_EQ(p.option, (std::vector<int>{1, 0}));
  // A table without the far frame does not move along the footprint.
  t.farFramePx = std::nan("");
  EXPECT_NEAR(err(0, 40.0), 0.087 * 0.087, 1e-12);
}

// The atlas's truth is noisy: a lower mean error it did not resolve (a large standard error of
// the paired difference) must not win over a slightly higher one it did.
TEST(QualityController, AnUnresolvedLeadDoesNotWinOnTheTruthsNoise) {
  QualityTable t;
  QualityOption noisy = option("ray-march", "10", 0.20, 1.0, 1e-4);
  noisy.squaredStderr.fill(0.05);  // 0.04 +- 0.05: the truth cannot tell it from 0.09
  QualityOption resolved = option("texture-space", "6g-opt", 0.25, 1.0, 1e-4);
  resolved.squaredStderr.fill(0.001);
  t.options = {option("lit", "default", 0.5, 0.1, 1e-5), noisy, resolved};
  const std::vector<ObjectView> one(1, objects()[1]);
  ControllerSettings s;
  const Plan charged = choosePlan(t, priors(t), 0.0, one, kScreenPx, 100.0, s);
  ASSERT_TRUE(charged.fits);
  EXPECT_EQ(t.options[std::size_t(charged.option[0])].method, "texture-space");
  // The charged error: sqrt(e^2 + 1 s.e.) on the object's view (poked: e = 0.25 x 1.1).
  EXPECT_NEAR(charged.expectedError, std::sqrt(0.275 * 0.275 + 0.001), 1e-12);
  s.errorConfidence = 0.0;  // the means alone: the noisy lead wins
  const Plan means = choosePlan(t, priors(t), 0.0, one, kScreenPx, 100.0, s);
  EXPECT_EQ(t.options[std::size_t(means.option[0])].method, "ray-march");
}

// `frames` frames of `c` under `budget`: each frame's overhead is `overhead(f)` ms (called
// first), each object's measured cost `measure(f, choice, trueMs)` with trueMs its option's table
// cost at its footprint (the machine's true cost). Returns each frame's measured ms.
std::vector<double> simulate(QualityController& c, const std::vector<ObjectView>& objs, double budget,
                             int frames, const std::function<double(int)>& overhead,
                             const std::function<double(int, const ObjectChoice&, double)>& measure) {
  const QualityTable& t = c.table();
  std::vector<double> out;
  for (int f = 0; f < frames; ++f) {
    const auto& ch = c.update(objs, kScreenPx, budget);
    std::vector<CostSample> samples;
    double frame = overhead(f);
    for (std::size_t i = 0; i < ch.size(); ++i) {
      const QualityOption& o = t.options[std::size_t(ch[i].option)];
      samples.push_back({i, measure(f, ch[i], o.fixedMs + o.msPerPx * objs[i].footprintPx)});
      frame += samples.back().ms;
    }
    c.observe(samples, frame);
    out.push_back(frame);
  }
  return out;
}

// Measured costs the true ones times 4 % noise and, on odd frames, times `oddFactor` (even: 1 /
// oddFactor); the overhead the table's.
void runFrames(QualityController& c, const std::vector<ObjectView>& objs, double budget, int frames,
               std::mt19937& rng, double oddFactor) {
  std::normal_distribution<double> noise(1.0, 0.04);  // 4% measurement noise
  simulate(
      c, objs, budget, frames, [&](int) { return c.table().frameOverheadMs; },
      [&](int f, const ObjectChoice&, double ms) {
        return ms * noise(rng) * (f % 2 ? oddFactor : 1.0 / oddFactor);
      });
}

// A scene offers an option once its settings are built (Scene::budgetOptionsPending): the
// controller asks at once whether it gains, not after the hold.
TEST(QualityController, AnOptionOfferedAnewIsWeighedAtOnce) {
  const QualityTable t = table();
  ControllerSettings s;
  s.holdFrames = 1000;
  QualityController c(t, s);
  std::vector<ObjectView> objs(1);
  objs[0].footprintPx = 3000;
  objs[0].allowed = {t.find("lit", "default"), t.find("lit", "wrap")};
  for (int f = 0; f < 3; ++f)
    EXPECT_EQ(c.update(objs, kScreenPx, 1000.0)[0].method, "lit");
  objs[0].allowed.push_back(t.find("ray-march", "50"));  // built meanwhile
  EXPECT_EQ(c.update(objs, kScreenPx, 1000.0)[0].setting, "50");
  // The same offer again: the plan is held.
  const int changes = c.plansChanged();
  for (int f = 0; f < 5; ++f)
    c.update(objs, kScreenPx, 1000.0);
  EXPECT_EQ(c.plansChanged(), changes);
}

// Budgets from none fitting to the edge of the cheapest plan, costs with 4 % noise (and swinging
// 5 % frame to frame): once settled, the plan holds. Two rules keep it so. A plan over the
// budget within the tolerance is not searched before the hold (searching it every
// overRecheckFrames, tried, made 14 changes in 300 frames at 8 ms: it fits and does not by the
// noise). A drop where nothing fits must save more than the headroom (costs that close are one
// cost).
TEST(QualityController, AtTheEdgeOfTheBudgetThePlanDoesNotChurnOnTheCostsNoise) {
  ControllerSettings s;
  s.holdFrames = 10;
  const auto objs = objects();
  for (double budget : {2.5, 3.0, 4.0, 6.0, 7.0, 8.0, 9.0})
    for (double odd : {1.0, 1.05}) {
      QualityController c(table(), s);
      std::mt19937 rng(8);
      runFrames(c, objs, budget, 40, rng, odd);  // settle
      const int settled = c.plansChanged();
      runFrames(c, objs, budget, 300, rng, odd);
      EXPECT_LE(c.plansChanged() - settled, 1) << budget << " ms, swing " << odd;
    }
}

TEST(QualityController, HysteresisHoldsThePlanUnderNoisyCosts) {
  ControllerSettings s;
  s.holdFrames = 10;
  QualityController c(table(), s);
  const auto objs = objects();
  const double budget = 14.0;
  std::mt19937 rng(3);
  runFrames(c, objs, budget, 60, rng, 1.0);  // settle on the true costs
  const int changesAfterSettling = c.plansChanged();
  const std::vector<int> held = c.plan().option;
  runFrames(c, objs, budget, 300, rng, 1.0);
  EXPECT_EQ(c.plansChanged(), changesAfterSettling);
  EXPECT_EQ(c.plan().option, held);
  // Without hysteresis (and learning from each frame alone) costs swinging by 25% do change the
  // plan: the test can fail.
  ControllerSettings none = s;
  none.holdFrames = 0;
  none.gainMargin = 0.0;
  none.overBudgetTolerance = 0.0;
  none.learningRate = 1.0;
  QualityController jumpy(table(), none);
  std::mt19937 rng2(3);
  runFrames(jumpy, objs, budget, 360, rng2, 1.25);
  EXPECT_GT(jumpy.plansChanged(), 2);
  // The same swings with hysteresis: the held plan stays.
  QualityController steady(table(), s);
  std::mt19937 rng3(3);
  runFrames(steady, objs, budget, 60, rng3, 1.0);
  const int settled = steady.plansChanged();
  runFrames(steady, objs, budget, 300, rng3, 1.04);
  EXPECT_EQ(steady.plansChanged(), settled);
  // A new budget is planned for at once, hold or not.
  const auto& loose = steady.update(objs, kScreenPx, 1000.0);
  EXPECT_EQ(loose[0].setting, "50");
}

// Frames as runFrames (4% noise, no swing), where an object's first frame with a new option
// costs `spikeMs` more (its pass and the frame): the one-off cost of a switch.
std::vector<double> runSpiked(QualityController& c, const std::vector<ObjectView>& objs, double budget,
                              int frames, std::mt19937& rng, double spikeMs) {
  std::normal_distribution<double> noise(1.0, 0.04);
  return simulate(
      c, objs, budget, frames, [&](int) { return c.table().frameOverheadMs; },
      [&](int, const ObjectChoice& ch, double ms) {
        return ms * noise(rng) + (ch.switched ? spikeMs : 0.0);
      });
}

TEST(QualityController, SwitchSpikesAreLearnedApartAndTheSwitchWaitsUntilItFits) {
  ControllerSettings s;
  s.holdFrames = 10;
  const QualityTable t = table();
  // The close-up alternates between two footprints every 40 frames, so the best plan under the
  // budget alternates too: each change is a switch with a one-off spike.
  auto scenario = [&](QualityController& c, double spikeMs, std::vector<double>& frames) {
    std::mt19937 rng(5);
    auto objs = objects();
    for (int phase = 0; phase < 10; ++phase) {
      objs[0].footprintPx = phase % 2 ? 20000.0 : 40000.0;
      const auto ms = runSpiked(c, objs, 14.0, 40, rng, spikeMs);
      frames.insert(frames.end(), ms.begin(), ms.end());
    }
  };
  // A spike that fits beside the cheaper plan: the plan follows the footprint, the spikes are
  // learned as the switch cost (the steady costs stay the table's), and nothing oscillates: one
  // change per phase at most.
  QualityController small(t, s);
  std::vector<double> smallFrames;
  scenario(small, 0.15, smallFrames);
  EXPECT_GE(small.plansChanged(), 5) << small.switchesDeferred() << " deferred";
  EXPECT_LE(small.plansChanged(), 11);
  for (std::size_t o = 0; o < t.options.size(); ++o) {
    const CostModel& m = small.costs()[o];
    if (m.samples == 0) continue;
    const double truth = t.options[o].fixedMs + t.options[o].msPerPx * 20000.0;
    EXPECT_NEAR(m.predictMs(20000.0), truth, 0.1 * truth)
        << t.options[o].method << " " << t.options[o].setting;
  }
  EXPECT_NEAR(small.overheadMs(), t.frameOverheadMs, 0.2);
  double learned = 0.0;
  for (double v : small.switchCostsMs())
    learned = std::max(learned, v);
  EXPECT_GT(learned, 0.05);
  EXPECT_LT(learned, 0.6);
  // A spike the budget cannot hold: once learned, the plan waits instead of breaking the budget
  // at every change (the first switch to each option teaches its cost).
  QualityController big(t, s);
  std::vector<double> bigFrames;
  scenario(big, 40.0, bigFrames);
  EXPECT_GT(big.switchesDeferred(), 0);
  int over = 0;
  for (std::size_t f = 1; f < bigFrames.size(); ++f)
    over += bigFrames[f] > 14.0 * 1.1 ? 1 : 0;
  EXPECT_LE(over, 3) << "frames over the budget: one per option first switched to";
}

// A stall outside the objects' passes (the host's own work, the OS: 4 frames of 10 ms overhead,
// not 2) drops the held plan, for its learned overhead puts it over the budget. The overhead is
// learned every frame and decays; after the drop the plan is searched every overRecheckFrames,
// and the plan made for the steady costs returns about 20 frames on. With the full hold it waits
// 30: the test can fail.
TEST(QualityController, APlanDroppedForAStallIsWeighedAgainSoon) {
  QualityTable t;
  t.options = {option("lit", "default", 0.50, 0.1, 1e-4), option("ray-march", "50", 0.12, 1.0, 8e-3)};
  t.frameOverheadMs = 2.0;
  std::vector<ObjectView> objs(1);
  objs[0].footprintPx = 1000.0;  // ray march 9 ms, lit 0.2 ms; frames 11 and 2.2 ms
  const double budget = 12.5;
  const int stall = 4, frames = 40;
  auto run = [&](int recheck) {
    ControllerSettings s;
    s.holdFrames = 30;
    s.overRecheckFrames = recheck;
    s.unmeasuredCostFactor = 1.0;  // the priors trusted: the stall is the test
    QualityController c(t, s);
    std::mt19937 rng(9);
    std::normal_distribution<double> noise(1.0, 0.02);
    const auto measured = [&](int, const ObjectChoice&, double ms) { return ms * noise(rng); };
    simulate(
        c, objs, budget, 60, [&](int) { return t.frameOverheadMs * noise(rng); }, measured);
    std::vector<std::string> method;  // per frame from the stall's first
    simulate(
        c, objs, budget, frames,
        [&](int f) {
          method.push_back(c.plan().option[0] == 1 ? "ray-march" : "lit");
          return f < stall ? 10.0 : t.frameOverheadMs * noise(rng);
        },
        measured);
    return method;
  };
  const auto soon = run(10), full = run(30);
  ASSERT_EQ(soon.front(), "ray-march");  // settled on the ray march
  // Dropped during the stall, in both (the same frames up to the first recheck).
  const auto drop = std::find(soon.begin(), soon.end(), "lit") - soon.begin();
  ASSERT_LE(drop, stall);
  ASSERT_EQ(std::vector(full.begin(), full.begin() + drop + 10),
            std::vector(soon.begin(), soon.begin() + drop + 10));
  // Back by the second recheck (the first finds the overhead not yet decayed); with the full hold
  // still on lit a hold later.
  const auto back = std::find(soon.begin() + drop, soon.end(), "ray-march") - soon.begin();
  EXPECT_LE(back, drop + 2 * 10 + 1);
  EXPECT_EQ(soon.back(), "ray-march");
  EXPECT_EQ(full[std::size_t(drop + 29)], "lit");
  EXPECT_EQ(full.back(), "ray-march");
}

// Frames whose every cost (objects and overhead) is the table's times one factor per frame,
// normal about 1 with relative spread `spread` (a shared machine's speed).
std::vector<double> runSharedNoise(QualityController& c, const std::vector<ObjectView>& objs, double budget,
                                   int frames, std::mt19937& rng, double spread) {
  std::normal_distribution<double> speed(1.0, spread);
  double k = 1.0;  // this frame's factor, drawn with its overhead
  return simulate(
      c, objs, budget, frames,
      [&](int) {
        k = std::max(0.3, speed(rng));
        return c.table().frameOverheadMs * k;
      },
      [&](int, const ObjectChoice&, double ms) { return ms * k; });
}

double p95(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[std::size_t(std::ceil(0.95 * double(v.size()))) - 1];
}

// One stall (a 3x frame) is not the spread of the frames: clipped at spreadClipSigmas it moves
// the learned spread by a third, where unclipped it made 2 % about 30 % (the test can fail).
// Frames that keep coming far out (every other one 1.3x) still grow it to theirs.
TEST(QualityController, OneStallDoesNotInflateTheSpread) {
  auto spreadAfter = [&](double clipSigmas, int stallFrames, double every = 0) {
    ControllerSettings s;
    s.spreadClipSigmas = clipSigmas;
    QualityController c(table(), s);
    std::mt19937 rng(4);
    std::normal_distribution<double> noise(1.0, 0.02);
    const auto objs = objects();
    simulate(
        c, objs, 14.0, 60, [&](int) { return c.table().frameOverheadMs; },
        [&](int, const ObjectChoice&, double ms) { return ms * noise(rng); });
    const double before = c.frameSpread();
    // every > 0: every other frame that much slower, else all `stallFrames` 3x
    const auto k = [&](int f) { return every > 0 ? (f % 2 ? every : 1.0) : 3.0; };
    simulate(
        c, objs, 14.0, stallFrames, [&](int f) { return k(f) * c.table().frameOverheadMs; },
        [&](int f, const ObjectChoice&, double ms) { return k(f) * ms; });
    return std::pair{before, c.frameSpread()};
  };
  const auto [before, clipped] = spreadAfter(3.0, 1);
  EXPECT_LT(before, 0.04);
  EXPECT_LT(clipped, 1.4 * before);
  EXPECT_GT(spreadAfter(0.0, 1).second, 0.25);
  EXPECT_GT(spreadAfter(3.0, 30, 1.3).second, 0.1);
}

TEST(QualityController, PlansForTheTailSoThe95thPercentileFitsTheBudget) {
  // Frame times swinging by 15 % (one factor on every cost of a frame): the learned spread is that
  // 15 %, and the plan made for budget / (1 + 1.645 x 0.15) keeps 95 % of the frames in the budget.
  const double budget = 14.0;
  ControllerSettings settings;
  settings.unmeasuredCostFactor = 1.0;  // every option tried at its prior: the tail alone keeps the budget
  QualityController tail(table(), settings);
  std::mt19937 rng(21);
  runSharedNoise(tail, objects(), budget, 80, rng, 0.15);  // settle
  const std::vector<double> ms = runSharedNoise(tail, objects(), budget, 600, rng, 0.15);
  EXPECT_NEAR(tail.frameSpread(), 0.15, 0.04);
  EXPECT_LE(p95(ms), budget * 1.03);
  EXPECT_NEAR(tail.planningBudgetMs(budget), budget / (1.0 + 1.645 * tail.frameSpread()), 1e-9);
  // Planning the mean (tailZ = 0) fills the budget on average and puts the 95th percentile
  // about 20 % over it: the test can fail.
  ControllerSettings mean = settings;
  mean.tailZ = 0.0;
  QualityController plain(table(), mean);
  std::mt19937 rng2(21);
  runSharedNoise(plain, objects(), budget, 80, rng2, 0.15);
  EXPECT_GT(p95(runSharedNoise(plain, objects(), budget, 600, rng2, 0.15)), budget * 1.1);
}

TEST(QualityController, AMeasuredSettingCalibratesItsUnmeasuredSiblings) {
  // The machine runs separable at 3x the table's cost. Only preintegrated-7 is ever drawn (the
  // objects allow it alone); preintegrated-17, never measured, is planned at 3x its prior too,
  // and the methods never measured at all at the ratio over every measured option (3x); here
  // without the extra factor for unmeasured options, which multiplies on top.
  const QualityTable t = table();
  ControllerSettings s;
  s.unmeasuredCostFactor = 1.0;
  QualityController c(t, s);
  auto objs = objects();
  for (ObjectView& v : objs)
    v.allowed = {2};             // separable preintegrated-7
  objs[4].footprintPx = 1000.0;  // above the fallback threshold
  simulate(
      c, objs, 1000.0, 40, [&](int) { return t.frameOverheadMs; },
      [](int, const ObjectChoice&, double ms) { return 3.0 * ms; });
  const auto planned = c.planningCosts();
  for (int o : {3, 4, 5, 6}) {  // separable-17 (sibling), texture space, ray march x 2
    const double prior = t.options[std::size_t(o)].fixedMs + t.options[std::size_t(o)].msPerPx * 5000.0;
    EXPECT_EQ(c.costs()[std::size_t(o)].samples, 0);
    EXPECT_NEAR(planned[std::size_t(o)].predictMs(5000.0), 3.0 * prior, 0.05 * 3.0 * prior)
        << t.options[std::size_t(o)].setting;
  }
  // Measured options keep their own learned cost.
  EXPECT_NEAR(planned[2].predictMs(5000.0), c.costs()[2].predictMs(5000.0), 1e-12);
  // Before any measurement the priors stand, times the factor for unmeasured options.
  QualityController fresh(t);
  EXPECT_NEAR(fresh.planningCosts()[3].predictMs(5000.0),
              1.5 * (t.options[3].fixedMs + t.options[3].msPerPx * 5000.0), 1e-12);
}

// Each cost term learns its own ratio: samples whose cost is the per-pixel part teach that
// part's ratio and leave the fixed part's at its fallback, and samples of both shapes teach both.
TEST(CostTermRatios, EachTermLearnsWhereItsSamplesSpendTheirCost) {
  EXPECT_EQ(termRatiosOf(CostTermRatios{}, {2.0, 0.5}), (std::array<double, 2>{2.0, 0.5}));
  // Both shapes, the machine 3x the priors: both terms 3.
  CostTermRatios both;
  for (int i = 0; i < 40; ++i) {
    const double a = i % 2 ? 1.0 : 0.2, b = i % 2 ? 0.1 : 3.0;
    observeTermRatios(both, a, b, 3.0 * (a + b), 0.1);
  }
  const auto r = termRatiosOf(both, {1.0, 1.0});
  EXPECT_NEAR(r[0], 3.0, 0.1);
  EXPECT_NEAR(r[1], 3.0, 0.1);
  // One shape, its cost per pixel (a line extrapolated past its footprints: 0.22 of its prior).
  // The pixel term takes the sample's ratio, (1 + 22) / 101; the fixed term, 1 % of the cost,
  // keeps the fallback, 2.
  CostTermRatios pixels;
  for (int i = 0; i < 40; ++i)
    observeTermRatios(pixels, 1.0, 100.0, 1.0 + 0.22 * 100.0, 0.1);
  const auto q = termRatiosOf(pixels, {2.0, 1.0});
  EXPECT_NEAR(q[0], 2.0, 0.05);
  EXPECT_NEAR(q[1], 23.0 / 101.0, 0.01);
  // Two methods pooled, nearly one cost split, ratios 0.22 and 1: the fixed term does not swing
  // (a least-squares fit of both terms puts it near 40).
  CostTermRatios pooled;
  for (int i = 0; i < 40; ++i) {
    observeTermRatios(pooled, 1.0, 100.0, 0.22 * 101.0, 0.1);
    observeTermRatios(pooled, 0.1, 3.0, 1.0 * 3.1, 0.1);
  }
  const auto u = termRatiosOf(pooled, {1.0, 1.0});
  EXPECT_GT(u[0], 0.7);
  EXPECT_LT(u[0], 1.1);
  EXPECT_GT(u[1], 0.22);
  EXPECT_LT(u[1], 1.0);
}

// The demo's first frames under a loose budget (docs/RESULTS.md, issue 16's thirteenth session):
// texture space's culled maps, measured on footprints far past the atlas's, cost 0.22 of their
// extrapolated prior; the uncut maps' cost is a fixed map size. Their planned cost stays their
// prior (times the factor for unmeasured options), not 0.22 of it; a per-pixel sibling takes 0.22.
TEST(QualityController, APerPixelRatioDoesNotPriceAFixedCostSibling) {
  QualityTable t;
  t.options = {option("lit", "default", 0.50, 0.1, 1e-4), option("texture-space", "default", 0.30, 1.0, 2e-3),
               option("texture-space", "6g-plain", 0.25, 900.0, 0.0),
               option("texture-space", "2g-culled", 0.28, 1.0, 3e-3)};
  t.frameOverheadMs = 2.0;
  QualityController c(t);
  std::vector<ObjectView> objs(3);
  objs[0].footprintPx = 50000.0;
  objs[1].footprintPx = 80000.0;
  objs[2].footprintPx = 30000.0;
  objs[0].allowed = objs[1].allowed = {1};
  objs[2].allowed = {0};
  simulate(
      c, objs, 1e6, 40, [&](int) { return t.frameOverheadMs; },
      [](int, const ObjectChoice& ch, double ms) { return ch.option == 1 ? 0.22 * ms : ms; });
  const auto planned = c.planningCosts();
  const double factor = ControllerSettings{}.unmeasuredCostFactor;
  EXPECT_EQ(c.costs()[2].samples, 0);
  EXPECT_GT(planned[2].predictMs(60000.0), 0.8 * factor * 900.0);
  EXPECT_LT(planned[2].predictMs(60000.0), 1.2 * factor * 900.0);
  const double perPixel = 1.0 + 3e-3 * 60000.0;
  EXPECT_NEAR(planned[3].predictMs(60000.0), 0.22 * factor * perPixel, 0.03 * factor * perPixel);
}

// Frames drawn with options the host chose (no budget) teach the controller their costs, so
// that the first plan under a budget starts from this machine's; a frame with an option new to
// an object (its one-off work) teaches nothing.
TEST(QualityController, FramesTheHostChoseTeachTheCosts) {
  const QualityTable t = table();
  QualityController c(t);
  const double px = 5000.0;
  const auto prior = [&](int o) {
    return t.options[std::size_t(o)].fixedMs + t.options[std::size_t(o)].msPerPx * px;
  };
  // A first frame of its option: nothing learned.
  const OptionCostSample first[] = {{2, px, 3.0 * prior(2), true}, {0, px, prior(0), false}};
  c.observeUnplanned(first, {}, 100.0);
  EXPECT_EQ(c.costs()[2].samples, 0);
  EXPECT_EQ(c.costs()[0].samples, 0);
  // Separable preintegrated-7 at 3x its prior, lit at its prior, 4 ms of overhead.
  for (int f = 0; f < 30; ++f) {
    const OptionCostSample frame[] = {{2, px, 3.0 * prior(2), false}, {0, px, prior(0), false}};
    c.observeUnplanned(frame, {}, 4.0 + 3.0 * prior(2) + prior(0));
  }
  EXPECT_EQ(c.costs()[2].samples, 30);
  EXPECT_NEAR(c.costs()[2].predictMs(px), 3.0 * prior(2), 1e-9);
  EXPECT_NEAR(c.overheadMs(), 4.0, 0.1);  // from the table's 2 ms, an EMA of 0.1 over 30 frames
  // Its unmeasured sibling is calibrated by it: 3x its prior (times the factor for unmeasured).
  const double calibrated = 3.0 * ControllerSettings{}.unmeasuredCostFactor * prior(3);
  EXPECT_NEAR(c.planningCosts()[3].predictMs(px), calibrated, 0.1 * calibrated);
  // An option not in the table teaches nothing.
  const OptionCostSample bad[] = {{99, px, 1.0, false}};
  c.observeUnplanned(bad, {}, 5.0);
  EXPECT_EQ(c.costs()[2].samples, 30);
}

// A host's new budget is planned for at once; a held plan that fits it is left only where the
// switch frame fits too (the one-off costs learned), as with a gain found after holding. A budget
// nudged by less than the gain margin is the same budget: no search before holdFrames.
TEST(QualityController, ANewBudgetWaitsForASwitchFrameThatFits) {
  ControllerSettings s;
  s.holdFrames = 10;
  const QualityTable t = table();
  QualityController c(t, s);
  std::mt19937 rng(5);
  auto objs = objects();
  // Switches cost 40 ms once: learned while the close-up's footprint alternates, ending on the
  // larger footprint (the held plan then fits the smaller one).
  for (int phase = 0; phase < 11; ++phase) {
    objs[0].footprintPx = phase % 2 ? 20000.0 : 40000.0;
    runSpiked(c, objs, 14.0, 40, rng, 40.0);
  }
  const std::vector<int> held = c.plan().option;
  objs[0].footprintPx = 20000.0;  // the other phase's footprint: its best plan differs
  const Plan best = choosePlan(t, c.planningCosts(), c.overheadMs(), objs, kScreenPx,
                               c.planningBudgetMs(16.0), s, c.planningPassMs());
  ASSERT_NE(best.option, held) << "the scenario must offer a change";
  const int deferred = c.switchesDeferred();
  c.update(objs, kScreenPx, 14.2);  // nudged: the held plan, not even asked
  EXPECT_EQ(c.plan().option, held);
  EXPECT_EQ(c.switchesDeferred(), deferred);
  c.update(objs, kScreenPx, 16.0);  // new: asked at once, the switch frame does not fit
  EXPECT_EQ(c.plan().option, held);
  EXPECT_EQ(c.switchesDeferred(), deferred + 1);
  // A budget with room for the switch frame takes the change at once.
  c.update(objs, kScreenPx, 1000.0);
  EXPECT_NE(c.plan().option, held);
}

// Options of one work (QualityOption::costClass: d'Eon's and the pre-integrated kernel at 11
// taps) learn one cost: a sample of one is a sample of the other, so the plan chooses between
// them by error and not by which one's measurements the machine's noise flattered.
TEST(QualityController, OptionsOfOneCostClassLearnOneCost) {
  QualityTable t;
  t.options = {option("lit", "default", 0.50, 0.1, 1e-4), option("separable", "deon-11", 0.40, 0.8, 3e-4),
               option("separable", "preintegrated-11", 0.35, 0.8, 3e-4)};
  t.frameOverheadMs = 2.0;
  t.options[1].costClass = t.options[2].costClass = 0;
  t.costClasses = {"separable-11"};
  ControllerSettings s;
  s.unmeasuredCostFactor = 1.0;
  auto objs = objects();
  for (ObjectView& v : objs)
    v.allowed = {1};  // deon-11 alone is drawn and measured, at 1.3 x its prior
  objs[4].footprintPx = 1000.0;
  const auto run = [&](const QualityTable& table) {
    QualityController c(table, s);
    simulate(
        c, objs, 1000.0, 30, [&](int) { return table.frameOverheadMs; },
        [](int, const ObjectChoice&, double ms) { return 1.3 * ms; });
    return c;
  };
  const QualityController shared = run(t);
  const CostModel& deon = shared.costs()[1];
  const CostModel& pre = shared.costs()[2];
  EXPECT_GT(deon.samples, 0);
  EXPECT_EQ(pre.samples, deon.samples);
  EXPECT_DOUBLE_EQ(pre.predictMs(5000.0), deon.predictMs(5000.0));
  EXPECT_NEAR(deon.predictMs(5000.0), 1.3 * (0.8 + 3e-4 * 5000.0), 0.01);
  // Without the class the sibling has never been measured: its own prior (here 1 x, calibrated
  // by the method's measured ratio: planningCosts) stands.
  QualityTable apart = t;
  apart.options[1].costClass = apart.options[2].costClass = -1;
  const QualityController alone = run(apart);
  EXPECT_EQ(alone.costs()[2].samples, 0);
}

TEST(QualityController, LearnedCostConvergesToTheMeasuredCost) {
  // The prior is 3x off; the machine's cost is 1.5 ms + 4e-4 ms/px.
  CostModel m = costModelOf(option("separable", "x", 0.3, 0.5, 1.2e-3));
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> px(500.0, 20000.0);
  std::normal_distribution<double> noise(1.0, 0.05);
  for (int i = 0; i < 400; ++i) {
    const double x = px(rng);
    observeCost(m, x, (1.5 + 4e-4 * x) * noise(rng), 0.05);
  }
  for (double x : {1000.0, 10000.0, 20000.0})
    EXPECT_NEAR(m.predictMs(x), 1.5 + 4e-4 * x, 0.08 * (1.5 + 4e-4 * x));
  // At one footprint only, the prediction at that footprint converges too.
  CostModel fixed = costModelOf(option("lit", "y", 0.5, 0.2, 1e-4));
  for (int i = 0; i < 200; ++i)
    observeCost(fixed, 5000.0, 3.0 * noise(rng), 0.1);
  EXPECT_NEAR(fixed.predictMs(5000.0), 3.0, 0.15);
}

// A line fitted between two small objects (the fallback tier's far organs, 30 and 61 px) is
// their timing noise as much as their cost: past the footprints it was measured at, the prior's
// slope, not the fitted one (which priced lit at 50 ms on a 5000 px close-up on the budget bench,
// run 62) nor the prior's scaled by the measured level (the small objects' per-object work over a
// prior without it: 220 ms, run 63).
TEST(QualityController, ALineLearnedOnSmallObjectsIsNotExtrapolatedToALargeOne) {
  CostModel m = costModelOf(option("lit", "default", 0.1, 0.0, 5e-4));  // lit: no prior per object
  const auto truth = [](double px) { return 1.2 + 5e-4 * px; };
  for (int i = 0; i < 60; ++i) {
    const double px = i % 2 ? 61.0 : 30.0;
    observeCost(m, px, truth(px) * (i % 2 ? 1.1 : 0.9), 0.05);  // the larger one measured 20 % slower
  }
  EXPECT_GT(m.msPerPx, 0.005);                       // the fitted slope is the noise's: 10x the cost's
  EXPECT_NEAR(m.predictMs(45.0), truth(45.0), 0.1);  // within the measured footprints, the fit
  EXPECT_LT(m.fittedToPx, 100.0);                    // which reaches about as far as they do
  EXPECT_NEAR(m.predictMs(5000.0), truth(5000.0), 0.25 * truth(5000.0));  // past them, the prior's slope
  // Measured across the footprints it is used at, the fitted line holds everywhere it was measured.
  CostModel wide = costModelOf(option("lit", "default", 0.1, 1.0, 5e-4));
  for (int i = 0; i < 200; ++i) {
    const double px = 30.0 + 25.0 * double(i % 200);
    observeCost(wide, px, 0.5 + 2e-3 * px, 0.05);
  }
  EXPECT_NEAR(wide.predictMs(4000.0), 0.5 + 2e-3 * 4000.0, 0.05 * (0.5 + 2e-3 * 4000.0));
}

// A method's passes of no object (separable's screen-space blurs) are paid once per plan that
// uses the method, whatever the number of its objects: the plan is the exact optimum of that
// cost, checked against every assignment of options to objects.
TEST(QualityController, AMethodsOwnPassesArePaidOncePerPlan) {
  const QualityTable t = table();
  const auto costs = priors(t);
  // Separable's blurs 4 ms, texture space's copy 1 ms; the others have none.
  std::vector<double> pass(t.options.size(), 0.0);
  for (std::size_t o = 0; o < t.options.size(); ++o) {
    if (t.options[o].method == "separable") pass[o] = 4.0;
    if (t.options[o].method == "texture-space") pass[o] = 1.0;
  }
  std::vector<ObjectView> objs(4);
  objs[0].footprintPx = 20000;
  objs[1].footprintPx = 5000;
  objs[2].footprintPx = 2500;
  objs[3].footprintPx = 1200;
  const ControllerSettings s;
  const std::size_t n = objs.size(), k = t.options.size();
  const auto predicted = [&](const std::vector<int>& o) {
    double ms = t.frameOverheadMs;
    std::vector<std::string> used;
    for (std::size_t i = 0; i < n; ++i) {
      ms += costs[std::size_t(o[i])].predictMs(objs[i].footprintPx);
      const std::string& m = t.options[std::size_t(o[i])].method;
      if (std::find(used.begin(), used.end(), m) == used.end()) {
        used.push_back(m);
        ms += pass[std::size_t(o[i])];
      }
    }
    return ms;
  };
  int separableShared = 0;
  for (double budget = 4.0; budget < 120.0; budget *= 1.17) {
    const Plan p = choosePlan(t, costs, t.frameOverheadMs, objs, kScreenPx, budget, s, pass);
    ASSERT_EQ(p.option.size(), n);
    EXPECT_NEAR(p.predictedMs, predicted(p.option), 1e-9) << "each method's passes once";
    const double free = budget * (1.0 - s.headroom);
    // Every assignment: the least error within the budget, and within it less the grid's
    // rounding (one grid step per object).
    double best = 1e30, bestWithSlack = 1e30;
    std::vector<int> o(n, 0);
    for (std::size_t code = 0; code < std::size_t(std::pow(double(k), double(n))); ++code) {
      std::size_t c = code;
      for (std::size_t i = 0; i < n; ++i, c /= k)
        o[i] = int(c % k);
      const double ms = predicted(o);
      const double e =
          evaluatePlan(t, costs, t.frameOverheadMs, objs, kScreenPx, o, budget, s, pass).expectedError;
      if (ms <= free) best = std::min(best, e);
      if (ms <= free - double(n) * s.costGridMs) bestWithSlack = std::min(bestWithSlack, e);
    }
    if (best > 1e29) {
      EXPECT_FALSE(p.fits) << budget;
      continue;
    }
    ASSERT_TRUE(p.fits) << budget;
    EXPECT_LE(p.predictedMs, free + 1e-9) << budget;
    EXPECT_GE(p.expectedError, best - 1e-12) << budget;
    EXPECT_LE(p.expectedError, bestWithSlack + 1e-12) << budget;
    int separable = 0;
    for (int x : p.option)
      separable += t.options[std::size_t(x)].method == "separable";
    if (separable >= 2) ++separableShared;
  }
  EXPECT_GT(separableShared, 0) << "some budget puts several objects under one separable pass";
}

// The controller learns a method's own passes from its pass samples, apart from its objects'
// costs, and charges them once: two separable objects are predicted at one pass plus two objects.
TEST(QualityController, LearnsAMethodsOwnPassesApartFromItsObjects) {
  QualityTable t;
  t.options = {option("lit", "default", 0.50, 0.5, 1e-4),
               option("separable", "preintegrated-7", 0.30, 0.5, 1e-4)};
  t.frameOverheadMs = 1.0;
  ControllerSettings s;
  s.tailZ = 0.0;
  QualityController c(t, s);
  std::vector<ObjectView> objs(2);
  objs[0].footprintPx = 8000;
  objs[1].footprintPx = 4000;
  const double objectMs = 0.2, passMs = 5.0;  // this machine: the blurs cost, the draws hardly
  for (int f = 0; f < 80; ++f) {
    const auto& ch = c.update(objs, kScreenPx, 100.0);
    std::vector<CostSample> samples;
    double frame = 1.0;
    bool anySeparable = false;
    for (std::size_t i = 0; i < ch.size(); ++i) {
      samples.push_back({i, objectMs});
      frame += objectMs;
      anySeparable = anySeparable || ch[i].method == "separable";
    }
    std::vector<PassSample> passes;
    if (anySeparable) {
      passes.push_back({"separable", passMs});
      frame += passMs;
    }
    c.observe(samples, passes, frame);
  }
  for (const auto& ch : c.choices())
    EXPECT_EQ(ch.method, "separable") << "the budget fits both";
  const auto pass = c.planningPassMs();
  EXPECT_NEAR(pass[1], passMs, 1e-6);
  EXPECT_NEAR(pass[0], 0.0, 1e-12) << "lit was never measured with passes of its own";
  EXPECT_NEAR(c.plan().predictedMs, 1.0 + passMs + 2 * objectMs, 0.05) << "the pass once, not per object";
  EXPECT_NEAR(c.overheadMs(), 1.0, 0.05);
}

TEST(QualityController, MeshWorkFollowsTheMethod) {
  EXPECT_FALSE(meshWorkOf("lit", false).planes);
  EXPECT_FALSE(meshWorkOf("lit", false).tangents);
  EXPECT_TRUE(meshWorkOf("lit", true).tangents);
  EXPECT_FALSE(meshWorkOf("separable", true).planes);
  EXPECT_TRUE(meshWorkOf("ray-march", false).planes);
  EXPECT_TRUE(meshWorkOf("ray-march", false).tangents);
  EXPECT_FALSE(meshWorkOf("parallax", false).planes);
  EXPECT_TRUE(meshWorkOf("parallax", false).tangents);
}

TEST(QualityController, ViewClassFromFootprintAngleAndDeformation) {
  ObjectView v;
  v.footprintPx = 0.5 * kScreenPx;
  EXPECT_EQ(viewClassOf(v, kScreenPx), ViewClass::CloseUp);
  v.footprintPx = 2000;
  EXPECT_EQ(viewClassOf(v, kScreenPx), ViewClass::Rest);
  v.deforming = true;
  EXPECT_EQ(viewClassOf(v, kScreenPx), ViewClass::Deforming);
  v.viewAngleDeg = 85;
  EXPECT_EQ(viewClassOf(v, kScreenPx), ViewClass::Grazing);
  v.deforming = false;
  v.viewAngleDeg = 50;
  EXPECT_EQ(viewClassOf(v, kScreenPx), ViewClass::Oblique);
  v.viewAngleDeg = 60;
  EXPECT_EQ(viewClassOf(v, kScreenPx), ViewClass::Low);
  v.viewAngleDeg = 20;
  EXPECT_EQ(viewClassOf(v, kScreenPx), ViewClass::Rest);
}

// Two options whose errors cross along the view angle, as the atlas's ray march and separable do
// at grazing view: A leads at the rest frame's 25 degrees, B at the grazing frame's 80.
QualityTable angleTable() {
  QualityTable t;
  QualityOption a = option("ray-march", "50", 0.0, 1.0, 1e-4),
                b = option("separable", "guided-25", 0.0, 1.0, 1e-4);
  const auto set = [](QualityOption& o, ViewClass c, double e) { o.relRms[std::size_t(c)] = e; };
  set(a, ViewClass::Rest, 0.10), set(a, ViewClass::Oblique, 0.20), set(a, ViewClass::Low, 0.25);
  set(a, ViewClass::Grazing, 0.30);
  set(a, ViewClass::CloseUp, 0.15), set(a, ViewClass::Deforming, 0.12);
  set(b, ViewClass::Rest, 0.20), set(b, ViewClass::Oblique, 0.20), set(b, ViewClass::Low, 0.20);
  set(b, ViewClass::Grazing, 0.20);
  set(b, ViewClass::CloseUp, 0.18), set(b, ViewClass::Deforming, 0.22);
  t.options = {a, b};
  t.viewAngleDeg[std::size_t(ViewClass::Rest)] = 25;
  t.viewAngleDeg[std::size_t(ViewClass::Deforming)] = 25;
  t.viewAngleDeg[std::size_t(ViewClass::CloseUp)] = 25;
  t.viewAngleDeg[std::size_t(ViewClass::Oblique)] = 45;
  t.viewAngleDeg[std::size_t(ViewClass::Low)] = 60;
  t.viewAngleDeg[std::size_t(ViewClass::Grazing)] = 80;
  return t;
}

TEST(QualityController, TheExpectedErrorFollowsTheViewAngleBetweenTheAtlasFrames) {
  const QualityTable t = angleTable();
  ControllerSettings s;
  s.errorConfidence = 0.0;
  ObjectView v;
  const auto e = [&](double angle, ViewClass c) {
    v.viewAngleDeg = angle;
    return expectedSquaredError(t, 0, v, c, s);
  };
  // On the frames' own angles, the frames' errors; between them, linear in the angle.
  EXPECT_NEAR(e(25, ViewClass::Rest), 0.01, 1e-12);
  EXPECT_NEAR(e(45, ViewClass::Oblique), 0.04, 1e-12);
  EXPECT_NEAR(e(60, ViewClass::Low), 0.0625, 1e-12);
  EXPECT_NEAR(e(80, ViewClass::Grazing), 0.09, 1e-12);
  EXPECT_NEAR(e(35, ViewClass::Rest), 0.025, 1e-12);
  EXPECT_NEAR(e(35, ViewClass::Oblique), 0.025, 1e-12);      // the class names the frame; the angle rules
  EXPECT_NEAR(e(52.5, ViewClass::Oblique), 0.05125, 1e-12);  // between oblique and low
  EXPECT_NEAR(e(70, ViewClass::Low), 0.07625, 1e-12);        // between low and grazing
  // Constant beyond the ends.
  EXPECT_NEAR(e(0, ViewClass::Rest), 0.01, 1e-12);
  EXPECT_NEAR(e(89, ViewClass::Grazing), 0.09, 1e-12);
  // A close-up (or a deforming organ) pays the angle's change from its frame's angle on top of its
  // own frame's error: the close-up at 45 degrees, 0.0225 + (0.04 - 0.01).
  EXPECT_NEAR(e(45, ViewClass::CloseUp), 0.0525, 1e-12);
  EXPECT_NEAR(e(25, ViewClass::CloseUp), 0.0225, 1e-12);
  // Never below zero: B's close-up error falls with the angle less than its rest error rises.
  QualityTable falling = t;
  falling.options[1].relRms[std::size_t(ViewClass::Grazing)] = 0.0;
  v.viewAngleDeg = 80;
  EXPECT_NEAR(expectedSquaredError(falling, 1, v, ViewClass::CloseUp, s), 0.0, 1e-12);  // 0.0324 - 0.04
  // Without the frames' angles (an older atlas), the class's own error at any angle.
  QualityTable old = t;
  old.viewAngleDeg.fill(kNoAngle);
  v.viewAngleDeg = 60;
  EXPECT_NEAR(expectedSquaredError(old, 0, v, ViewClass::CloseUp, s), 0.0225, 1e-12);
  // The confidence charge moves with the angle as the error does.
  QualityTable charged = t;
  charged.options[0].squaredStderr[std::size_t(ViewClass::Oblique)] = 0.002;
  s.errorConfidence = 1.0;
  v.viewAngleDeg = 45;
  EXPECT_NEAR(expectedSquaredError(charged, 0, v, ViewClass::Oblique, s), 0.042, 1e-12);
}

TEST(QualityController, AnOrganSeenObliquelyTakesTheOptionThatLeadsAtItsAngle) {
  const QualityTable t = angleTable();
  const std::vector<CostModel> costs = priors(t);
  std::vector<ObjectView> views(1);
  views[0].footprintPx = 0.5 * kScreenPx;  // a close-up
  ControllerSettings s;
  s.errorConfidence = 0.0;
  views[0].viewAngleDeg = 25;  // as the atlas's close-up: A (0.0225 against 0.0324)
  EXPECT_EQ(choosePlan(t, costs, 0.0, views, kScreenPx, 1e3, s).option, std::vector<int>{0});
  views[0].viewAngleDeg = 50;  // A 0.0225 + 0.0475 - 0.01 = 0.06, B 0.0324 + 0
  EXPECT_EQ(choosePlan(t, costs, 0.0, views, kScreenPx, 1e3, s).option, std::vector<int>{1});
}

}  // namespace
}  // namespace tissue::quality
