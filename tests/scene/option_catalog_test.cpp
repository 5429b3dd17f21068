// The option catalog (issue 16): each organ's offered quality-table options, their renderer
// settings built on a worker (lit's at once), offered to the controller as they are built, the
// ones that cannot be built never offered. GL-free: settings hold texture handles only.
#include "tissue/scene/option_catalog.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <variant>

#include "../studies/data_organ.h"
#include "tissue/quality/quality_table.h"
#include "tissue/scene/budget.h"

namespace tissue::scene {
namespace {

OrganSource dataLiver() {
  return studies::testdata::dataOrgan("liver");
}

TEST(OptionCatalog, BuildsEveryOfferedOptionOffTheCallersThreadAndOffersTheBuiltOnes) {
  auto assets = loadOrganAssets(dataLiver());
  ASSERT_TRUE(assets) << assets.error().message;
  const quality::QualityTable& table = quality::defaultQualityTable();
  const std::vector<int> offered = offeredOptions(table, *assets);
  OptionCatalog catalog;
  EXPECT_EQ(catalog.pending(), 0u);
  EXPECT_TRUE(catalog.ready(0).empty());
  // No textures were uploaded (no GL): the ray march's and parallax's settings need theirs, so
  // those options fail on the worker and are never offered; the others build.
  catalog.offer(0, table, *assets, OrganTextures{}, MethodChoices{});
  EXPECT_TRUE(catalog.offered(0));
  // Lit's are built at once: the first frame has a choice.
  const std::vector<int> first = catalog.ready(0);
  ASSERT_FALSE(first.empty());
  for (int k : first)
    EXPECT_EQ(table.options[std::size_t(k)].method, "lit");
  catalog.finish();
  EXPECT_EQ(catalog.pending(), 0u);
  const std::vector<int> all = catalog.ready(0);
  for (int k : offered) {
    const std::string& method = table.options[std::size_t(k)].method;
    const bool built = std::find(all.begin(), all.end(), k) != all.end();
    const bool needsTextures = method == "ray-march" || method == "parallax";
    EXPECT_EQ(built, !needsTextures) << method << " " << table.options[std::size_t(k)].setting;
    EXPECT_EQ(catalog.settings(0, k) != nullptr, built);
  }
  // A built separable option's settings are the same as built on the caller's thread.
  const int sep = table.find("separable", "preintegrated-17");
  ASSERT_GE(sep, 0);
  const auto direct =
      methodOfOption(table.options[std::size_t(sep)], *assets, OrganTextures{}, MethodChoices{});
  ASSERT_TRUE(direct);
  const render::MethodSettings* built = catalog.settings(0, sep);
  ASSERT_NE(built, nullptr);
  ASSERT_TRUE(std::holds_alternative<render::SeparableSettings>(*built));
  const auto& a = std::get<render::SeparableSettings>(*built).components;
  const auto& b = std::get<render::SeparableSettings>(*direct).components;
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t r = 0; r < a.size(); ++r) {
    ASSERT_EQ(a[r].taps.size(), b[r].taps.size());
    for (std::size_t t = 0; t < a[r].taps.size(); ++t)
      EXPECT_EQ(a[r].taps[t].x, b[r].taps[t].x);  // the same fit, bit for bit
  }
  // Offering the organ again changes nothing.
  catalog.offer(0, table, *assets, OrganTextures{}, MethodChoices{});
  EXPECT_EQ(catalog.pending(), 0u);
  // A failed option asked for anyway says why.
  const int march = table.find("ray-march", "50");
  ASSERT_GE(march, 0);
  const auto refused = catalog.chosen(0, march, table, *assets, OrganTextures{}, MethodChoices{});
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.error().message.find("subsurface map"), std::string::npos) << refused.error().message;
}

TEST(OptionCatalog, ADestroyedCatalogStopsItsWorker) {
  auto assets = loadOrganAssets(dataLiver());
  ASSERT_TRUE(assets) << assets.error().message;
  {
    OptionCatalog catalog;
    catalog.offer(0, quality::defaultQualityTable(), *assets, OrganTextures{}, MethodChoices{});
    catalog.offer(1, quality::defaultQualityTable(), *assets, OrganTextures{}, MethodChoices{});
    EXPECT_GT(catalog.pending(), 0u);
  }  // joins after the fit under way; nothing is left running (the sanitizers' run checks leaks)
}

}  // namespace
}  // namespace tissue::scene
