// The quality controller's plan search (issue 16): choosePlan on the committed default table for
// the budget bench's five organs, with no method passes (one knapsack) and with separable's and
// texture space's own passes (one knapsack per set of methods, docs/DECISIONS.md "Each object's
// passes are its own"). Prints median, p99 and max ms per search over many calls, both measured
// in one run.
#include <cstdio>
#include <vector>

#include "tissue/core/statistics.h"
#include "tissue/core/stopwatch.h"
#include "tissue/quality/controller.h"

namespace {

using namespace tissue;

SampleSummary timeSearches(const quality::QualityTable& table, std::span<const quality::CostModel> costs,
                           std::span<const quality::ObjectView> objects, double budgetMs,
                           std::span<const double> passMs, int calls, double& error) {
  std::vector<double> ms;
  ms.reserve(std::size_t(calls));
  for (int i = 0; i < calls; ++i) {
    const Stopwatch watch;
    const quality::Plan p = quality::choosePlan(table, costs, table.frameOverheadMs, objects, 256.0 * 192.0,
                                                budgetMs, {}, passMs);
    ms.push_back(watch.elapsedMs());
    error = p.expectedError;
  }
  return summarizeSamples(ms);
}

}  // namespace

int main() {
  const quality::QualityTable& table = quality::defaultQualityTable();
  std::vector<quality::CostModel> costs;
  for (const quality::QualityOption& o : table.options)
    costs.push_back(quality::costModelOf(o));
  // The budget bench's organs at 256 x 192 (close-up, two mid, two far: docs/RESULTS.md).
  std::vector<quality::ObjectView> objects(5);
  const double px[5] = {7885, 2229, 1500, 300, 150};
  for (std::size_t i = 0; i < objects.size(); ++i)
    objects[i].footprintPx = px[i];
  objects[0].deforming = true;
  std::vector<double> passes(table.options.size(), 0.0);
  for (std::size_t o = 0; o < table.options.size(); ++o) {
    if (table.options[o].method == "separable") passes[o] = 3.0;
    if (table.options[o].method == "texture-space") passes[o] = 0.5;
  }
  std::printf("choosePlan, %zu options, %zu objects, ms per search (median / p99 / max, 2000 calls)\n",
              table.options.size(), objects.size());
  for (double budget : {30.0, 60.0, 120.0}) {
    double e0 = 0.0, e1 = 0.0;
    const SampleSummary none = timeSearches(table, costs, objects, budget, {}, 2000, e0);
    const SampleSummary sets = timeSearches(table, costs, objects, budget, passes, 2000, e1);
    std::printf(
        "budget %5.0f ms: no passes %.3f / %.3f / %.3f (error %.4f); by method set %.3f / %.3f / %.3f "
        "(error %.4f); ratio of medians %.1f\n",
        budget, none.median, none.p99, none.max, e0, sets.median, sets.p99, sets.max, e1,
        sets.median / none.median);
  }
  return 0;
}
