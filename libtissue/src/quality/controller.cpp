// The quality controller (controller.h): the view class, the learned costs, the exact plan under
// the budget and the held plan's hysteresis.
#include "tissue/quality/controller.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace tissue::quality {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMaxCostUnits = 4000.0;  // the knapsack's columns at most (choosePlan)

int wrapOption(const QualityTable& table, const ControllerSettings& s) {
  const int wrap = table.find(s.wrapMethod, s.wrapSetting);
  return wrap >= 0 ? wrap : table.find(s.wrapMethod, "default");
}

// The options object `view` may take. Below the footprint threshold, the fallback tier: the
// fallback method with its wrap term and without it, whichever the table's error for the view
// (and the cost) prefers. The wrap term stands in for the scattering lit lacks (Unreal
// Substrate's Wrap tier); where the truth shows it adds error, the tier is plain lit.
std::vector<int> candidatesOf(const QualityTable& table, const ObjectView& view,
                              const ControllerSettings& s) {
  std::vector<int> out;
  const int wrap = wrapOption(table, s);
  if (view.footprintPx < s.minFootprintPx && wrap >= 0) {
    const int plain = table.find(s.wrapMethod, "default");
    if (plain >= 0 && plain != wrap) return {wrap, plain};
    return {wrap};
  }
  if (view.allowed.empty()) {
    for (std::size_t o = 0; o < table.options.size(); ++o)
      out.push_back(int(o));
  } else {
    for (int o : view.allowed)
      if (o >= 0 && std::size_t(o) < table.options.size()) out.push_back(o);
  }
  if (out.empty() && wrap >= 0) out.push_back(wrap);
  return out;
}

double weightOf(const ObjectView& v) {
  return std::max(0.0, v.importance) * std::max(0.0, v.footprintPx);
}

// One sample x into the mean v of n samples so far (sampleWeight).
void runningEma(double& v, int& n, double x, double rate) {
  const double a = sampleWeight(n, rate);
  v = (1 - a) * v + a * x;
  ++n;
}

double costOf(std::span<const CostModel> costs, int option, const ObjectView& v) {
  return std::max(0.0, costs[std::size_t(option)].predictMs(std::max(0.0, v.footprintPx)));
}

bool objectsWithoutCandidate(const std::vector<std::vector<int>>& cand) {
  return std::any_of(cand.begin(), cand.end(), [](const std::vector<int>& c) { return c.empty(); });
}

// The exact multiple-choice knapsack: the options (one of cand[i] per object) of least
// sum w e^2 whose costs, rounded up to a grid, sum to at most `freeMs`; empty where none does.
// best[i][k] = least sum w e^2 of objects < i within k grid units (rounded up, so a plan found
// fits). Monotone in k, hence in the budget.
std::vector<int> leastErrorWithin(const QualityTable& table, std::span<const CostModel> costs,
                                  std::span<const ObjectView> objects,
                                  const std::vector<std::vector<int>>& cand, double screenPx, double freeMs,
                                  const ControllerSettings& s) {
  const std::size_t n = objects.size();
  if (!(freeMs >= 0.0)) return {};
  // At most kMaxCostUnits grid units: a budget far above any cost (a host's "no limit") coarsens
  // the grid instead of growing the table (bounded time and memory).
  const double grid = std::max({s.costGridMs, 1e-4, freeMs / kMaxCostUnits});
  const long K = long(std::floor(freeMs / grid + 1e-9));
  const std::size_t cols = std::size_t(K) + 1;
  std::vector<double> prev(cols, 0.0), next(cols);
  std::vector<std::vector<int>> pick(n, std::vector<int>(cols, -1));
  for (std::size_t i = 0; i < n; ++i) {
    const ViewClass view = viewClassOf(objects[i], screenPx, s);
    const double w = weightOf(objects[i]);
    std::fill(next.begin(), next.end(), kInf);
    for (int o : cand[i]) {
      const long u = long(std::ceil(costOf(costs, o, objects[i]) / grid - 1e-9));
      const double term = w * expectedSquaredError(table, o, objects[i], view, s);
      for (long k = u; k < long(cols); ++k) {
        const double v = prev[std::size_t(k - u)] + term;
        // Ties go to the cheaper option (fewer units used), for a steady choice.
        if (v < next[std::size_t(k)] - 1e-15) {
          next[std::size_t(k)] = v;
          pick[i][std::size_t(k)] = o;
        }
      }
    }
    std::swap(prev, next);
  }
  if (!std::isfinite(prev[std::size_t(K)])) return {};
  std::vector<int> option(n, -1);
  long k = K;
  for (std::size_t i = n; i-- > 0;) {
    const int o = pick[i][std::size_t(k)];
    option[i] = o;
    k -= long(std::ceil(costOf(costs, o, objects[i]) / grid - 1e-9));
  }
  return option;
}

}  // namespace

MeshWork meshWorkOf(std::string_view method, bool hasNormalMap) {
  MeshWork w;
  w.planes = method == "ray-march";  // François et al. 2006 eq. 9-10: the light's entry via the planes
  // The ray march steps along T and B; parallax offsets the inner layers in tangent space
  // (Norberg eq. 15-18); every method's normal map is in tangent space.
  w.tangents = hasNormalMap || method == "ray-march" || method == "parallax";
  return w;
}

ViewClass viewClassOf(const ObjectView& v, double screenPx, const ControllerSettings& s) {
  if (v.footprintPx >= s.closeUpFraction * screenPx ||
      (s.closeUpDistanceMm > 0.0 && v.distanceMm < s.closeUpDistanceMm))
    return ViewClass::CloseUp;
  if (v.viewAngleDeg >= s.grazingDeg) return ViewClass::Grazing;
  if (v.deforming) return ViewClass::Deforming;
  if (v.viewAngleDeg >= s.lowDeg) return ViewClass::Low;
  if (v.viewAngleDeg >= s.obliqueDeg) return ViewClass::Oblique;
  return ViewClass::Rest;
}

namespace {

// The table's charged squared error of `option` on the frame of class v.
double chargedOnFrame(const QualityOption& option, std::size_t v, const ControllerSettings& s) {
  const double e = option.relRms[v];
  return e * e + std::max(0.0, s.errorConfidence) * option.squaredStderr[v];
}

// The option's charged squared error along the view angle: piecewise linear between the atlas's
// frames of one distance that differ in angle (rest, oblique, low, grazing), constant beyond the ends;
// none (nan) where the table has fewer than two of them with an angle.
double alongAngle(const QualityTable& table, const QualityOption& option, double angleDeg,
                  const ControllerSettings& s) {
  std::array<std::pair<double, double>, 4> curve{};  // (angle, charged e^2); no allocation per call
  std::size_t n = 0;
  for (ViewClass c : {ViewClass::Rest, ViewClass::Oblique, ViewClass::Low, ViewClass::Grazing})
    if (const double a = table.viewAngleDeg[std::size_t(c)]; std::isfinite(a))
      curve[n++] = {a, chargedOnFrame(option, std::size_t(c), s)};
  if (n < 2) return std::nan("");
  for (std::size_t i = 1; i < n; ++i)  // by angle (insertion: four at most)
    for (std::size_t j = i; j > 0 && curve[j].first < curve[j - 1].first; --j)
      std::swap(curve[j], curve[j - 1]);
  if (angleDeg <= curve[0].first) return curve[0].second;
  for (std::size_t k = 1; k < n; ++k)
    if (angleDeg <= curve[k].first) {
      const auto& [a0, e0] = curve[k - 1];
      const auto& [a1, e1] = curve[k];
      const double t = a1 > a0 ? (angleDeg - a0) / (a1 - a0) : 1.0;
      return e0 + t * (e1 - e0);
    }
  return curve[n - 1].second;
}

// The option's charged squared error along the footprint at the low frame's angle: linear in
// ln px between the far frame (the low view from 2.5x the distance) and the low frame, constant
// beyond them; nan where the table lacks either. An object of fewer pixels is more of its
// silhouette and its shading's angular shape, where the methods part most (the far frame's
// lit 0.1185 against the ray march's 0.097, debiased; at the low frame 0.087 against 0.086).
double alongFootprint(const QualityTable& table, const QualityOption& option, double px,
                      const ControllerSettings& s) {
  const auto low = std::size_t(ViewClass::Low);
  const double pxFar = table.farFramePx, pxLow = table.framePx[low];
  if (!(pxFar > 0.0) || !(pxLow > pxFar) || !std::isfinite(option.farRelRms)) return std::nan("");
  const double eFar =
      option.farRelRms * option.farRelRms + std::max(0.0, s.errorConfidence) * option.farSquaredStderr;
  const double eLow = chargedOnFrame(option, low, s);
  if (!(px > pxFar)) return eFar;
  if (px >= pxLow) return eLow;
  const double t = std::log(px / pxFar) / std::log(pxLow / pxFar);
  return eFar + t * (eLow - eFar);
}

}  // namespace

double expectedSquaredError(const QualityTable& table, int option, const ObjectView& view, ViewClass cls,
                            const ControllerSettings& s) {
  const QualityOption& o = table.options[std::size_t(option)];
  double e = chargedOnFrame(o, std::size_t(cls), s);
  // Moved along the angle from the class frame's to the object's.
  if (const double frameAngle = table.viewAngleDeg[std::size_t(cls)]; std::isfinite(frameAngle)) {
    const double here = alongAngle(table, o, view.viewAngleDeg, s);
    const double there = alongAngle(table, o, frameAngle, s);
    if (std::isfinite(here) && std::isfinite(there)) e += here - there;
  }
  // And along the footprint from the class frame's pixels to the object's.
  if (const double framePx = table.framePx[std::size_t(cls)]; std::isfinite(framePx)) {
    const double here = alongFootprint(table, o, view.footprintPx, s);
    const double there = alongFootprint(table, o, framePx, s);
    if (std::isfinite(here) && std::isfinite(there)) e += here - there;
  }
  return std::max(0.0, e);
}

namespace {

// The methods of the table's options: a name per method, and each option's method index.
struct MethodIndex {
  std::vector<std::string> names;
  std::vector<std::size_t> of;  // per option
};
MethodIndex methodIndexOf(const QualityTable& table) {
  MethodIndex m;
  for (const QualityOption& o : table.options) {
    const auto it = std::find(m.names.begin(), m.names.end(), o.method);
    m.of.push_back(std::size_t(it - m.names.begin()));
    if (it == m.names.end()) m.names.push_back(o.method);
  }
  return m;
}

// The passes of no object that `option`'s methods run: each method's once (passMs per option).
double passesOf(const MethodIndex& methods, std::span<const double> passMs, std::span<const int> option) {
  if (passMs.empty()) return 0.0;
  std::vector<bool> used(methods.names.size(), false);
  double ms = 0.0;
  for (int o : option) {
    if (o < 0 || std::size_t(o) >= passMs.size() || used[methods.of[std::size_t(o)]]) continue;
    used[methods.of[std::size_t(o)]] = true;
    ms += std::max(0.0, passMs[std::size_t(o)]);
  }
  return ms;
}

// The options of `cand` in the method set `mask` that no other of them beats on both cost and
// charged error (a dominated option is never in an optimal plan: the knapsack need not see it).
std::vector<int> frontOf(const QualityTable& table, std::span<const CostModel> costs,
                         const MethodIndex& methods, const std::vector<int>& cand, unsigned mask,
                         const ObjectView& view, ViewClass cls, const ControllerSettings& s) {
  std::vector<std::pair<double, int>> byCost;
  for (int o : cand)
    if (const std::size_t m = methods.of[std::size_t(o)]; m >= 32 || (mask & (1u << m)))
      byCost.push_back({costOf(costs, o, view), o});
  std::stable_sort(byCost.begin(), byCost.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<int> out;
  double least = kInf;
  for (const auto& [cost, o] : byCost) {
    const double e = expectedSquaredError(table, o, view, cls, s);
    if (e < least - 1e-15) {
      out.push_back(o);
      least = e;
    }
  }
  return out;
}

}  // namespace

Plan evaluatePlan(const QualityTable& table, std::span<const CostModel> costs, double overheadMs,
                  std::span<const ObjectView> objects, double screenPx, std::vector<int> option,
                  double budgetMs, const ControllerSettings& s, std::span<const double> passMs) {
  Plan p;
  p.option = std::move(option);
  p.predictedMs = overheadMs + passesOf(methodIndexOf(table), passMs, p.option);
  double we = 0.0, w = 0.0;
  for (std::size_t i = 0; i < objects.size() && i < p.option.size(); ++i) {
    const int o = p.option[i];
    p.predictedMs += costOf(costs, o, objects[i]);
    we += weightOf(objects[i]) *
          expectedSquaredError(table, o, objects[i], viewClassOf(objects[i], screenPx, s), s);
    w += weightOf(objects[i]);
  }
  p.expectedError = w > 0.0 ? std::sqrt(we / w) : 0.0;
  p.fits = p.predictedMs <= budgetMs * (1.0 - s.headroom);
  return p;
}

Plan choosePlan(const QualityTable& table, std::span<const CostModel> costs, double overheadMs,
                std::span<const ObjectView> objects, double screenPx, double budgetMs,
                const ControllerSettings& s, std::span<const double> passMs) {
  const std::size_t n = objects.size();
  std::vector<std::vector<int>> cand(n);
  for (std::size_t i = 0; i < n; ++i)
    cand[i] = candidatesOf(table, objects[i], s);
  const MethodIndex methods = methodIndexOf(table);
  // Each method's passes of no object (the value its options carry).
  std::vector<double> methodPass(methods.names.size(), 0.0);
  if (passMs.size() == table.options.size())
    for (std::size_t o = 0; o < passMs.size(); ++o)
      methodPass[methods.of[o]] = std::max(methodPass[methods.of[o]], std::max(0.0, passMs[o]));
  // The method sets a plan may use, each paying its methods' passes once: the methods without
  // passes of their own always (allowing them costs nothing), with every subset of the others.
  // More than 6 methods with passes (or more than 32 methods): all at once, all passes paid.
  unsigned always = 0;
  std::vector<std::size_t> paid;
  for (std::size_t m = 0; m < methodPass.size() && m < 32; ++m) {
    if (methodPass[m] > 0.0)
      paid.push_back(m);
    else
      always |= 1u << m;
  }
  std::vector<unsigned> sets;
  std::vector<double> setPassMs;
  if (paid.size() > 6 || methods.names.size() > 32) {
    sets.push_back(~0u);
    setPassMs.push_back(0.0);
    for (double ms : methodPass)
      setPassMs.back() += ms;
  } else {
    for (unsigned sub = 0; sub < (1u << paid.size()); ++sub) {
      unsigned mask = always;
      double ms = 0.0;
      for (std::size_t j = 0; j < paid.size(); ++j)
        if (sub & (1u << j)) {
          mask |= 1u << paid[j];
          ms += methodPass[paid[j]];
        }
      if (mask == 0) continue;
      sets.push_back(mask);
      setPassMs.push_back(ms);
    }
  }
  std::vector<int> option;
  bool fits = false;
  if (!objectsWithoutCandidate(cand)) {
    // Each set's candidates, pruned to the options no other beats on cost and error.
    std::vector<std::vector<std::vector<int>>> front(sets.size(), std::vector<std::vector<int>>(n));
    std::vector<bool> usable(sets.size(), true);
    double cheapest = kInf;  // the cheapest plan's cost over the sets, their passes included
    for (std::size_t k = 0; k < sets.size(); ++k) {
      double c = setPassMs[k];
      for (std::size_t i = 0; i < n && usable[k]; ++i) {
        front[k][i] = frontOf(table, costs, methods, cand[i], sets[k], objects[i],
                              viewClassOf(objects[i], screenPx, s), s);
        if (front[k][i].empty())
          usable[k] = false;
        else
          c += costOf(costs, front[k][i].front(), objects[i]);  // the cheapest comes first
      }
      if (usable[k]) cheapest = std::min(cheapest, c);
    }
    // Where even the cheapest plan does not fit, the plan of least error within the headroom
    // above it (the learned costs' own noise), not each object's cheapest option, which that
    // noise picks among options of one cost (plain lit or its wrap term).
    const double free = budgetMs * (1.0 - s.headroom) - overheadMs;
    fits = cheapest <= free;
    const double grid = std::max({s.costGridMs, 1e-4, 2.0 * cheapest / kMaxCostUnits});
    const double limit = fits ? free : cheapest * (1.0 + s.headroom) + 2.0 * double(n) * grid;
    double bestError = kInf, bestMs = kInf;
    for (std::size_t k = 0; k < sets.size(); ++k) {
      if (!usable[k] || setPassMs[k] > limit) continue;
      std::vector<int> o =
          leastErrorWithin(table, costs, objects, front[k], screenPx, limit - setPassMs[k], s);
      if (o.empty()) continue;
      const Plan p = evaluatePlan(table, costs, overheadMs, objects, screenPx, o, budgetMs, s, passMs);
      // Ties go to the cheaper plan, for a steady choice.
      if (p.expectedError < bestError - 1e-12 ||
          (p.expectedError <= bestError + 1e-12 && p.predictedMs < bestMs)) {
        bestError = p.expectedError;
        bestMs = p.predictedMs;
        option = std::move(o);
      }
    }
    fits = fits && !option.empty();
  }
  if (option.empty()) {  // an object without candidates (or the grid's rounding): each one's cheapest
    option.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      double best = kInf;
      for (int o : cand[i])
        if (const double c = costOf(costs, o, objects[i]); c < best) {
          best = c;
          option[i] = o;
        }
    }
  }
  Plan p = evaluatePlan(table, costs, overheadMs, objects, screenPx, std::move(option), budgetMs, s, passMs);
  p.fits = fits;
  return p;
}

QualityController::QualityController(QualityTable table, ControllerSettings settings)
    : m_table(std::move(table)), m_settings(std::move(settings)) {
  for (const QualityOption& o : m_table.options)
    m_costs.push_back(costModelOf(o));
  m_overheadMs = m_table.frameOverheadMs;
  m_switchMs.assign(m_table.options.size(), 0.0);
  MethodIndex methods = methodIndexOf(m_table);
  m_methods = std::move(methods.names);
  m_optionMethod = std::move(methods.of);
  m_methodRatios.assign(m_methods.size(), {});
  m_switchSamples.assign(m_table.options.size(), 0);
  m_passMs.assign(m_methods.size(), 0.0);
  m_passSamples.assign(m_methods.size(), 0);
}

std::vector<CostModel> QualityController::planningCosts() const {
  std::vector<CostModel> out = m_costs;
  for (std::size_t o = 0; o < out.size(); ++o) {
    if (out[o].samples > 0) continue;
    const auto ratio = termRatiosOf(m_methodRatios[m_optionMethod[o]], termRatiosOf(m_allRatios, {1.0, 1.0}));
    const double k = std::max(1.0, m_settings.unmeasuredCostFactor);
    out[o].fixedMs *= ratio[0] * k;
    out[o].msPerPx *= ratio[1] * k;
  }
  return out;
}

std::vector<double> QualityController::planningPassMs() const {
  std::vector<double> out(m_table.options.size(), 0.0);
  for (std::size_t o = 0; o < out.size(); ++o)
    out[o] = m_passMs[m_optionMethod[o]];
  return out;
}

double QualityController::planningBudgetMs(double budgetMs) const {
  return budgetMs / (1.0 + std::max(0.0, m_settings.tailZ) * frameSpread());
}

const std::vector<ObjectChoice>& QualityController::update(std::span<const ObjectView> objects,
                                                           double screenPx, double budgetMs) {
  const ControllerSettings& s = m_settings;
  // Plans are made for the tail (ControllerSettings::tailZ): a plan whose mean fits the budget
  // puts half its frames over it.
  const double tail = 1.0 + std::max(0.0, s.tailZ) * frameSpread();
  const std::vector<CostModel> costs = planningCosts();
  const std::vector<double> passMs = planningPassMs();
  // A new set of objects: the held plan was made for something else. A new budget (one that
  // differs from the held plan's by more than newBudgetFraction): the plan is searched again at
  // once and taken for any gain, but a held plan that fits it is left only where the switch
  // frame fits too (a host's new budget is no reason to break it once). A budget nudged by less
  // (a host setting it each frame from a measured refresh) is the same budget: the held plan's
  // hysteresis stands.
  bool replace = m_plan.option.size() != objects.size();
  const bool newBudget = !(std::abs(budgetMs - m_budgetMs) <= s.newBudgetFraction * m_budgetMs);
  if (newBudget || replace) m_budgetMs = budgetMs;
  if (!replace) {
    // The held plan must still be allowed for each object (a footprint below the threshold
    // takes the fallback at once).
    for (std::size_t i = 0; i < objects.size() && !replace; ++i) {
      const auto cand = candidatesOf(m_table, objects[i], s);
      replace = std::find(cand.begin(), cand.end(), m_plan.option[i]) == cand.end();
    }
  }
  Plan held, best;
  if (!replace) {
    held = evaluatePlan(m_table, costs, m_overheadMs, objects, screenPx, m_plan.option, budgetMs / tail, s,
                        passMs);
    // The plan is searched only where it may change: held too long to keep without asking, or
    // over the budget.
    const bool overHeld = held.predictedMs * tail > budgetMs * (1.0 + s.overBudgetTolerance);
    // Options offered anew (a host's scene builds settings off the frame path and offers them as
    // they are ready): worth asking at once, not after the hold.
    bool offerChanged = m_lastObjects.size() != objects.size();
    for (std::size_t i = 0; i < objects.size() && !offerChanged; ++i)
      offerChanged = objects[i].allowed != m_lastObjects[i].allowed;
    // Dropped for being over not long ago: searched every overRecheckFrames, not holdFrames.
    const bool recheck = m_sinceOverDrop >= 0 && m_sinceOverDrop < s.holdFrames;
    const int hold = recheck ? std::min(s.holdFrames, std::max(1, s.overRecheckFrames)) : s.holdFrames;
    const bool due = m_age >= hold || newBudget || offerChanged;
    if (due || overHeld) {
      best = choosePlan(m_table, costs, m_overheadMs, objects, screenPx, budgetMs / tail, s, passMs);
      // Left for being over: for a plan that fits, or, where none does, for one cheaper by more
      // than the headroom (costs that close are one cost; a drop within their noise churned
      // among options of about one cost, the budget bench's run 82: 16 changes in 60 frames).
      const bool over =
          overHeld && best.predictedMs < held.predictedMs * (best.fits ? 1.0 : 1.0 - s.headroom);
      bool gains = newBudget ? best.expectedError < held.expectedError - 1e-12
                             : due && best.expectedError < held.expectedError * (1.0 - s.gainMargin);
      if (gains) {
        // The switch frame itself must fit: the new plan plus the one-off costs of the options
        // it gives objects anew (a held plan that fits is no reason to break the budget once).
        double switchMs = 0.0;
        for (std::size_t i = 0; i < objects.size(); ++i)
          if (best.option[i] != m_plan.option[i]) switchMs += m_switchMs[std::size_t(best.option[i])];
        if (best.predictedMs + switchMs > budgetMs) {
          gains = false;
          ++m_deferred;
        }
      }
      replace = over || gains;
      // Asked and kept: the next question in holdFrames (a search per frame would cost a
      // knapsack per set of methods every frame: tissue_quality_bench); after a drop for being
      // over, every overRecheckFrames for a hold's length.
      if (!replace) m_age = 0;
      if (replace) m_sinceOverDrop = gains ? -1 : 0;
    }
  } else {
    best = choosePlan(m_table, costs, m_overheadMs, objects, screenPx, budgetMs / tail, s, passMs);
    m_sinceOverDrop = -1;
  }
  ++m_age;
  if (m_sinceOverDrop >= 0) ++m_sinceOverDrop;
  ++m_updates;
  const std::vector<int> before = m_plan.option;
  if (replace) {
    if (m_plan.option != best.option) {
      ++m_changes;
      m_meanSamples = 0;  // another plan: another mean frame time
      m_frameMean = 0.0;
    }
    m_plan = best;
    m_age = 0;
  } else {
    m_plan = held;
  }
  m_lastObjects.assign(objects.begin(), objects.end());
  m_choices.clear();
  ControllerSettings uncharged = s;  // the reported error: the table's, without the charge
  uncharged.errorConfidence = 0.0;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const int o = m_plan.option[i];
    const QualityOption& opt = m_table.options[std::size_t(o)];
    ObjectChoice c;
    c.option = o;
    c.method = opt.method;
    c.setting = opt.setting;
    c.predictedMs = costOf(costs, o, objects[i]);
    c.view = viewClassOf(objects[i], screenPx, s);
    c.expectedRelRms = std::sqrt(expectedSquaredError(m_table, o, objects[i], c.view, uncharged));
    c.fallback = objects[i].footprintPx < s.minFootprintPx;
    c.mesh = meshWorkOf(opt.method, objects[i].hasNormalMap);
    c.switched = before.size() == objects.size() && before[i] != o;
    m_choices.push_back(std::move(c));
  }
  return m_choices;
}

void QualityController::learnObject(int option, double px, double ms) {
  if (!std::isfinite(ms) || !std::isfinite(px)) return;
  const auto o = std::size_t(option);
  observeCost(m_costs[o], px, ms, m_settings.learningRate);
  // One work, one cost (QualityOption::costClass): a sample of deon-11 is one of
  // preintegrated-11 too, so that options of one cost are chosen by error, not by their noise.
  if (const int cls = m_table.options[o].costClass; cls >= 0)
    for (std::size_t sib = 0; sib < m_costs.size(); ++sib)
      if (m_table.options[sib].costClass == cls) m_costs[sib] = m_costs[o];
  // Measured over prior per cost term (planningCosts). The prior is an atlas frame's, one object
  // with its method's passes: the measured side adds them (to the fixed term).
  const QualityOption& opt = m_table.options[o];
  const std::size_t m = m_optionMethod[o];
  const double a = opt.fixedMs, b = opt.msPerPx * std::max(0.0, px);
  observeTermRatios(m_methodRatios[m], a, b, ms + m_passMs[m], m_settings.learningRate);
  observeTermRatios(m_allRatios, a, b, ms + m_passMs[m], m_settings.learningRate);
}

double QualityController::learnPasses(std::span<const PassSample> passes, const std::vector<bool>& learn) {
  double passesMs = 0.0;
  for (const PassSample& p : passes) {
    const auto it = std::find(m_methods.begin(), m_methods.end(), p.method);
    if (it == m_methods.end() || !std::isfinite(p.ms)) continue;
    const auto m = std::size_t(it - m_methods.begin());
    passesMs += std::max(0.0, p.ms);
    if (learn[m]) runningEma(m_passMs[m], m_passSamples[m], std::max(0.0, p.ms), m_settings.learningRate);
  }
  return passesMs;
}

void QualityController::observe(std::span<const CostSample> samples, std::span<const PassSample> passes,
                                double frameMs) {
  if (m_updates <= 1) return;  // the first frame builds everything: no steady cost
  std::vector<int> switchedTo;
  for (const ObjectChoice& c : m_choices)
    if (c.switched) switchedTo.push_back(c.option);
  // The methods' own passes: learned where the method has objects and none of them switched (a
  // switch frame's one-off work, a first kernel table, is not the method's steady cost).
  std::vector<bool> steady(m_methods.size(), false), switchedMethod(m_methods.size(), false);
  for (const ObjectChoice& c : m_choices) {
    const std::size_t m = m_optionMethod[std::size_t(c.option)];
    steady[m] = true;
    if (c.switched) switchedMethod[m] = true;
  }
  for (std::size_t m = 0; m < steady.size(); ++m)
    steady[m] = steady[m] && !switchedMethod[m];
  const double passesMs = learnPasses(passes, steady);
  double objectsMs = 0.0;
  for (const CostSample& c : samples) {
    if (c.object >= m_choices.size() || m_choices[c.object].switched) continue;
    learnObject(m_choices[c.object].option, m_lastObjects[c.object].footprintPx, c.ms);
    if (std::isfinite(c.ms)) objectsMs += c.ms;
  }
  if (!switchedTo.empty()) {
    // The excess over the plan's steady prediction, shared among the options switched to.
    if (!std::isfinite(frameMs)) return;
    const double excess = std::max(0.0, frameMs - m_plan.predictedMs) / double(switchedTo.size());
    for (int o : switchedTo)
      runningEma(m_switchMs[std::size_t(o)], m_switchSamples[std::size_t(o)], excess,
                 m_settings.learningRate);
    return;
  }
  if (std::isfinite(frameMs) && frameMs > 0.0) {
    // The frames' spread about their running mean under this plan (frameSpread). A frame beyond
    // spreadClipSigmas counts as one at that bound, in the mean too (a stall left in the mean
    // would put the next frames' deviations in the spread).
    double sample = frameMs;
    if (m_meanSamples > 0) {
      double r = (frameMs - m_frameMean) / m_frameMean;
      if (const double k = m_settings.spreadClipSigmas; k > 0.0 && m_frameSamples >= 5) {
        const double bound = k * std::sqrt(m_frameVar);
        r = std::clamp(r, -bound, bound);
        sample = m_frameMean * (1.0 + r);
      }
      runningEma(m_frameVar, m_frameSamples, std::min(r * r, 1.0), m_settings.learningRate);
    }
    runningEma(m_frameMean, m_meanSamples, sample, m_settings.learningRate);
  }
  learnOverhead(frameMs - objectsMs - passesMs);
}

void QualityController::observeUnplanned(std::span<const OptionCostSample> samples,
                                         std::span<const PassSample> passes, double frameMs) {
  const auto valid = [&](const OptionCostSample& c) {
    return c.option >= 0 && std::size_t(c.option) < m_table.options.size();
  };
  if (samples.empty() || !std::all_of(samples.begin(), samples.end(), valid) ||
      std::any_of(samples.begin(), samples.end(), [](const OptionCostSample& c) { return c.firstFrame; }))
    return;
  std::vector<bool> used(m_methods.size(), false);
  for (const OptionCostSample& c : samples)
    used[m_optionMethod[std::size_t(c.option)]] = true;
  const double passesMs = learnPasses(passes, used);
  double objectsMs = 0.0;
  for (const OptionCostSample& c : samples) {
    learnObject(c.option, c.footprintPx, c.ms);
    if (std::isfinite(c.ms)) objectsMs += c.ms;
  }
  learnOverhead(frameMs - objectsMs - passesMs);
}

void QualityController::learnOverhead(double ms) {
  if (!std::isfinite(ms)) return;
  const double a = std::clamp(m_settings.learningRate, 0.0, 1.0);
  m_overheadMs = (1 - a) * m_overheadMs + a * std::max(0.0, ms);
}

}  // namespace tissue::quality
