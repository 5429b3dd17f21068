// The material library: Jensen's table, d'Eon's Gaussians, the project's tissue materials.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "tissue/optics/materials.h"
#include "tissue/scene/material_file.h"

namespace tissue::optics {
namespace {

const std::filesystem::path kReference = std::filesystem::path(TISSUE_TEST_SHARED_DIR) / "reference";

TEST(Materials, JensenTableHasTwelveMaterialsFoundIgnoringCase) {
  auto all = loadJensenMaterials(kReference / "jensen2001_materials.tsv");
  ASSERT_TRUE(all.ok()) << all.error().message;
  EXPECT_EQ(all->size(), 12u);
  auto skin = findMaterial(*all, "skin1");
  ASSERT_TRUE(skin.ok());
  EXPECT_EQ(skin->name, "Skin1");
  EXPECT_EQ(skin->sigmaS[0], 0.74);
  EXPECT_EQ(skin->sigmaA[2], 0.48);
  EXPECT_EQ(skin->eta, 1.3);
  EXPECT_EQ(skin->sigmaSPrime(1), 0.88);
  EXPECT_TRUE(findMaterial(*all, "WHOLEMILK").ok());
  EXPECT_EQ(findMaterial(*all, "marble")->eta, 1.5);
  EXPECT_EQ(findMaterial(*all, "Chicken1")->sigmaA[0], 0.015);  // the corrected value, not 0.0015
  auto missing = findMaterial(*all, "skin3");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().message.find("Skin2"), std::string::npos);  // lists the known names
  const auto medium = halfSpace(*skin, 2);
  EXPECT_EQ(medium.layers[0].mua, 0.48);
  EXPECT_TRUE(std::isinf(medium.layers[0].thickness));
}

TEST(Materials, DeonColumnsSumToOneAndTheProfileIntegratesToOne) {
  auto sum = loadDeonGaussians(kReference / "deon_skin_gaussians.tsv");
  ASSERT_TRUE(sum.ok()) << sum.error().message;
  ASSERT_EQ(sum->varianceMm2.size(), 6u);
  for (int c = 0; c < kChannels; ++c) {
    double total = 0;
    for (double w : sum->weights[static_cast<std::size_t>(c)])
      total += w;
    EXPECT_NEAR(total, 1.0, 1e-9) << "channel " << c;
    // Integral of R(r) 2 pi r dr out to 30 mm (8 standard deviations of the widest Gaussian).
    const int n = 300000;
    const double h = 30.0 / n;
    double integral = 0;
    for (int i = 0; i < n; ++i) {
      const double r = (i + 0.5) * h;
      integral += gaussianSumProfile(*sum, c, r) * 2.0 * std::numbers::pi * r * h;
    }
    EXPECT_NEAR(integral, 1.0, 1e-6);
  }
}

// The project's material files are read by the scene module (the one reader); their first layer
// is the optical material of the separable kernels.
TEST(Materials, TissueMaterialUsesItsFirstLayer) {
  auto file =
      scene::readMaterialFile(std::filesystem::path(TISSUE_TEST_DATA_DIR) / "materials" / "liver.json");
  ASSERT_TRUE(file.ok()) << file.error().message;
  const auto liver = scene::opticalMaterial(*file);
  EXPECT_EQ(liver.name, "liver");
  // The parenchyma of shared/reference/liver_properties.md: Jacques 2013's fit to Parsa 1989,
  // mu_s' = 9.0 cm^-1 (lambda / 500 nm)^-0.617 at 640 / 460 nm, g = 0.9; the blood-content
  // absorption (B = 0.175, S = 0.75, Bosschaart 2014) at 640 nm. The file's numbers pass through
  // single precision (scene::MaterialLayer holds floats).
  EXPECT_NEAR(liver.sigmaSPrime(0), 0.9 * std::pow(640.0 / 500.0, -0.617), 1e-4);
  EXPECT_NEAR(liver.sigmaSPrime(2), 0.9 * std::pow(460.0 / 500.0, -0.617), 1e-4);
  EXPECT_NEAR(liver.sigmaA[0], 0.175 * (0.75 * 0.20 + 0.25 * 1.98), 1e-3);
  EXPECT_NEAR(liver.g, 0.9, 1e-6);
  EXPECT_NEAR(liver.eta, 1.38, 1e-6);
}

TEST(Materials, BadTablesAndFilesGiveErrorsNamingThePlace) {
  const auto dir = std::filesystem::path(TISSUE_TEST_OUTPUT_DIR) / "optics";
  std::filesystem::create_directories(dir);
  {
    std::ofstream(dir / "bad.tsv")
        << "material\tsps_R\n# comment\nSkin1\t0.74\t0.88\t1.01\t0.032\tx\t0.48\t1.3\n";
  }
  auto bad = loadJensenMaterials(dir / "bad.tsv");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message.find("line 3"), std::string::npos) << bad.error().message;
  EXPECT_NE(bad.error().message.find("'x'"), std::string::npos) << bad.error().message;
  EXPECT_FALSE(loadJensenMaterials(dir / "missing.tsv").ok());
  {
    std::ofstream(dir / "bad_material.json") << R"({"ior": 1.3, "layers": [{"g": 0.8, "sigma_s": [1, 1]}]})";
  }
  auto tissue = scene::readMaterialFile(dir / "bad_material.json");
  ASSERT_FALSE(tissue.ok());
  EXPECT_NE(tissue.error().message.find("bad_material.json"), std::string::npos) << tissue.error().message;
  EXPECT_NE(tissue.error().message.find("sigma_s"), std::string::npos) << tissue.error().message;
}

}  // namespace
}  // namespace tissue::optics
