// The one reader of material files and what every method derives from it.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "tissue/scene/material_file.h"
#include "tissue/scene/truth_material.h"

namespace tissue::scene {
namespace {

const std::filesystem::path kData = TISSUE_TEST_DATA_DIR;

std::filesystem::path writeFile(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::path(TISSUE_TEST_OUTPUT_DIR) / "scene" / "materials";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name) << text;
  return dir / name;
}

TEST(MaterialFile, TheDataLiverHasItsFiveLayersAndEveryTexture) {
  auto m = readMaterialFile(kData / "materials" / "liver.json");
  ASSERT_TRUE(m.ok()) << m.error().message;
  EXPECT_EQ(m->name, "liver");
  ASSERT_EQ(m->layers.size(), 5u);  // 4 boundaries of one RGBA map bound 4 + 1 layers (François §2.1)
  EXPECT_FLOAT_EQ(m->depthScaleMm, 3.0f);
  EXPECT_FLOAT_EQ(m->ior, 1.38f);  // Jacques 2013 eq. 3 with W = 0.7
  EXPECT_TRUE(m->baseColorDetail);
  for (const auto* t : {&m->textures.subsurface, &m->textures.baseColor, &m->textures.normalMap,
                        &m->textures.opacity, &m->textures.innerBase})
    EXPECT_TRUE(std::filesystem::exists(*t)) << t->string();
  // Each layer keeps sigma_t >= sigma_s > 0: absorption is what is left.
  for (const auto& l : m->layers) {
    EXPECT_GE(l.sigmaT.x, l.sigmaS.x);
    EXPECT_GT(l.sigmaS.x, 0.0f);
  }
}

TEST(MaterialFile, TheOpticalMaterialIsTheFirstLayerWithAbsorptionLeftOver) {
  auto m = readMaterialFile(kData / "materials" / "liver.json");
  ASSERT_TRUE(m.ok()) << m.error().message;
  const auto o = opticalMaterial(*m);
  const auto& l = m->layers.front();
  EXPECT_NEAR(o.sigmaA[0], double(l.sigmaT.x) - double(l.sigmaS.x), 1e-6);
  EXPECT_NEAR(o.sigmaA[2], double(l.sigmaT.z) - double(l.sigmaS.z), 1e-6);
  EXPECT_NEAR(o.sigmaS[1], double(l.sigmaS.y), 1e-6);
  EXPECT_NEAR(o.g, double(l.g), 1e-6);
  EXPECT_NEAR(o.eta, double(m->ior), 1e-6);
  EXPECT_FLOAT_EQ(firstLayerMinSigmaT(*m), std::min({l.sigmaT.x, l.sigmaT.y, l.sigmaT.z}));
}

// The truth's material (truth_material.h) from the same file and map: the truth renders the same organ.
void expectSameTruth(const MaterialFile* m, const Image8& map) {
  auto t = truthMaterial(*m, map);
  ASSERT_TRUE(t.ok()) << t.error().message;
  ASSERT_EQ(t->layers.size(), m->layers.size());
  EXPECT_EQ(t->maps.mapCount, 1);
  EXPECT_FLOAT_EQ(t->depthScaleMm, m->depthScaleMm);
  for (std::size_t i = 0; i < m->layers.size(); ++i) {
    const MaterialLayer& l = m->layers[i];
    EXPECT_NEAR((*t->layers[i].sigmaA)[1], double(l.sigmaT.y) - double(l.sigmaS.y), 1e-9);
    EXPECT_NEAR((*t->layers[i].sigmaS)[2], double(l.sigmaS.z), 1e-9);
    EXPECT_NEAR(t->layers[i].g[0], double(l.g), 1e-9);
    EXPECT_NEAR(t->layers[i].n, double(m->ior), 1e-6);
  }
  const double thickness[] = {0.5, 0.5, 0.5, 0.5};
  auto slab = truthMaterial(*m, thickness);
  ASSERT_TRUE(slab.ok()) << slab.error().message;
  EXPECT_DOUBLE_EQ(slab->layers[3].thicknessMm, 0.5);
  EXPECT_TRUE(std::isinf(slab->layers[4].thicknessMm));
  const double tooFew[] = {0.5};
  auto bad = truthMaterial(*m, tooFew);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message.find("liver.json"), std::string::npos);
}

TEST(MaterialFile, TheLayerStackAndTheTruthOfTheDataLiverValidate) {
  auto m = readMaterialFile(kData / "materials" / "liver.json");
  ASSERT_TRUE(m.ok()) << m.error().message;
  auto map = readImage(m->textures.subsurface, 4);
  ASSERT_TRUE(map.ok()) << map.error().message;
  auto stack = layerStack(*m, *map);
  ASSERT_TRUE(stack.ok()) << stack.error().message;
  expectSameTruth(&*m, *map);
  EXPECT_EQ(stack->boundaryCount(), 4);
  EXPECT_EQ(stack->layers.size(), 5u);
  EXPECT_FLOAT_EQ(stack->depthScaleMm, 3.0f);
}

TEST(MaterialFile, TheColourComesFromTheOptics) {
  auto m = readMaterialFile(kData / "materials" / "liver.json");
  ASSERT_TRUE(m.ok()) << m.error().message;
  // Liver is red: blood absorbs green and blue (Bosschaart 2014), so the albedo is red-dominant.
  const Float3 a = opticalAlbedo(*m);
  EXPECT_GT(a.x, 5.0f * a.y);
  EXPECT_GT(a.x, 5.0f * a.z);
  EXPECT_LT(a.x, 1.0f);
  // Blood (layer 2) reflects less red than the parenchyma: vessels show darker.
  EXPECT_LT(layerReflectance(*m, 2).total.x, a.x);
  // The artist's term: on, the painted luminance varies the texels; off, one flat albedo.
  Image8 painted(2, 1, 4);
  painted.at(0, 0)[0] = painted.at(0, 0)[1] = painted.at(0, 0)[2] = 60;
  painted.at(1, 0)[0] = painted.at(1, 0)[1] = painted.at(1, 0)[2] = 200;
  const Image8 detail = opticalBaseColor(*m, &painted);
  ASSERT_EQ(detail.width, 2);
  EXPECT_LT(detail.at(0, 0)[0], detail.at(1, 0)[0]);
  m->baseColorDetail = false;
  const Image8 flat = opticalBaseColor(*m, &painted);
  EXPECT_EQ(flat.at(0, 0)[0], flat.at(1, 1)[0]);
  EXPECT_EQ(flat.at(0, 0)[1], flat.at(3, 3)[1]);
  // sRGB of the linear albedo, red channel.
  const float r = a.x <= 0.0031308f ? 12.92f * a.x : 1.055f * std::pow(a.x, 1.0f / 2.4f) - 0.055f;
  EXPECT_NEAR(flat.at(0, 0)[0], 255.0f * r, 1.0f);
}

TEST(MaterialFile, ErrorsNameTheFileAndTheKey) {
  const auto missing = readMaterialFile(kData / "materials" / "no_such_organ.json");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().message.find("no_such_organ.json"), std::string::npos);

  const auto badSigma =
      writeFile("bad_sigma.json", R"({"layers": [{"sigma_s": [1, 1], "sigma_t": [2, 2, 2], "g": 0}]})");
  const auto a = readMaterialFile(badSigma);
  ASSERT_FALSE(a.ok());
  EXPECT_NE(a.error().message.find("bad_sigma.json"), std::string::npos);
  EXPECT_NE(a.error().message.find("layers[0]"), std::string::npos);
  EXPECT_NE(a.error().message.find("sigma_s"), std::string::npos);

  const auto gain =
      writeFile("gain.json", R"({"layers": [{"sigma_s": [3, 3, 3], "sigma_t": [2, 2, 2], "g": 0}]})");
  const auto b = readMaterialFile(gain);
  ASSERT_FALSE(b.ok());
  EXPECT_NE(b.error().message.find("sigma_t >= sigma_s"), std::string::npos);

  const auto noTexture = writeFile(
      "no_texture.json",
      R"({"layers": [{"sigma_s": [1, 1, 1], "sigma_t": [2, 2, 2], "g": 0.5}], "textures": {"base_color": "nowhere/x.png"}})");
  const auto c = readMaterialFile(noTexture);
  ASSERT_FALSE(c.ok());
  EXPECT_NE(c.error().message.find("nowhere/x.png"), std::string::npos);
  EXPECT_NE(c.error().message.find("textures.base_color"), std::string::npos);

  const auto notJson = writeFile("not_json.json", "{ layers: ");
  const auto d = readMaterialFile(notJson);
  ASSERT_FALSE(d.ok());
  EXPECT_NE(d.error().message.find("not a JSON object"), std::string::npos);

  // A name that is a number: nlohmann's value() throws type_error (the material fuzz target).
  const auto numberName = writeFile("number_name.json", R"({"name": 1.3, "source": "x"})");
  const auto e = readMaterialFile(numberName);
  ASSERT_FALSE(e.ok());
  EXPECT_NE(e.error().message.find("number_name.json: a value has the wrong type"), std::string::npos)
      << e.error().message;
  EXPECT_EQ(e.error().message.find('\n'), std::string::npos);
}

TEST(MaterialFile, TheDefaultMaterialIsAValidOrgan) {
  const auto m = defaultMaterial();
  ASSERT_EQ(m.layers.size(), 1u);
  const auto o = opticalMaterial(m);
  for (int c = 0; c < 3; ++c) {
    EXPECT_GT(o.sigmaA[std::size_t(c)], 0.0);
    EXPECT_GT(o.sigmaS[std::size_t(c)], 0.0);
  }
}

}  // namespace
}  // namespace tissue::scene
