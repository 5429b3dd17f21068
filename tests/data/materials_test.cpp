// The material files in data/materials parse and hold physically valid coefficients.
#include <gtest/gtest.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "tissue/core/atomic_file.h"

namespace tissue::datatest {
namespace {

namespace fs = std::filesystem;

TEST(DataMaterials, ParseWithPositiveCoefficientsAndSources) {
  const fs::path dir = fs::path(TISSUE_TEST_DATA_DIR);
  for (const char* name : {"patch", "liver", "tube"}) {
    const auto text = readTextFile(dir / "materials" / (std::string(name) + ".json"));
    ASSERT_TRUE(text.ok()) << text.error().message;
    const nlohmann::json m = nlohmann::json::parse(*text);
    EXPECT_EQ(m.at("name").get<std::string>(), name);
    EXPECT_GT(m.at("depth_scale_mm").get<double>(), 0.0);
    EXPECT_GT(m.at("ior").get<double>(), 1.0);
    EXPECT_LT(m.at("ior").get<double>(), 2.0);
    EXPECT_FALSE(m.at("source").get<std::string>().empty());
    const auto& layers = m.at("layers");
    ASSERT_EQ(layers.size(), 5u) << name;
    const char* tops[] = {"surface", "R", "G", "B", "A"};
    for (std::size_t i = 0; i < layers.size(); ++i) {
      const auto& layer = layers[i];
      EXPECT_EQ(layer.at("top").get<std::string>(), tops[i]) << name;
      EXPECT_FALSE(layer.at("name").get<std::string>().empty());
      EXPECT_GT(layer.at("source").get<std::string>().size(), 10u);
      const double g = layer.at("g").get<double>();
      EXPECT_GT(g, -1.0);
      EXPECT_LT(g, 1.0);
      const auto sigmaS = layer.at("sigma_s").get<std::vector<double>>();
      const auto sigmaT = layer.at("sigma_t").get<std::vector<double>>();
      ASSERT_EQ(sigmaS.size(), 3u);
      ASSERT_EQ(sigmaT.size(), 3u);
      for (int c = 0; c < 3; ++c) {
        EXPECT_GT(sigmaS[c], 0.0) << name << " layer " << i;
        EXPECT_GE(sigmaT[c], sigmaS[c]) << name << " layer " << i;  // sigma_a = sigma_t - sigma_s >= 0
        // Whole blood reaches about 130 mm^-1 (Bosschaart 2014); cm^-1 would be ten times that.
        EXPECT_LT(sigmaT[c], 1000.0) << name << " layer " << i << " (mm^-1, not cm^-1 or m^-1)";
      }
    }
    // The files named in the material exist.
    EXPECT_TRUE(fs::exists(dir / m.at("mesh").get<std::string>())) << name;
    for (const auto& [key, path] : m.at("textures").items()) {
      EXPECT_TRUE(fs::exists(dir / path.get<std::string>())) << name << " " << key;
    }
  }
}

}  // namespace
}  // namespace tissue::datatest
