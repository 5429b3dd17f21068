// Medium files: the format of `tissue-sim profile --medium`, and errors that name the key.
#include <gtest/gtest.h>

#include <cmath>

#include "tissue/optics/medium.h"

namespace tissue::optics {
namespace {

TEST(Medium, ParsesLayersAndInfiniteThickness) {
  auto m = parseMediumJson(
      R"({"ambient_n": 1.0, "layers": [{"n": 1.37, "mua": 0.1, "mus": 10, "g": 0.9, "thickness": 1},
                                      {"n": 1.4, "mua": 0.1, "mus": 9.9, "g": 0.9, "thickness": "inf"}]})",
      "m.json");
  ASSERT_TRUE(m.ok()) << m.error().message;
  ASSERT_EQ(m->layers.size(), 2u);
  EXPECT_EQ(m->layers[0].thickness, 1.0);
  EXPECT_TRUE(std::isinf(m->layers[1].thickness));
  EXPECT_EQ(m->ambientBelow, 1.0);
  EXPECT_NEAR(specularReflectance(*m), std::pow(0.37 / 2.37, 2), 1e-15);
}

// Each bad file gives one error naming the file and the offending key.
void expectError(const std::string& text, const std::string& key) {
  auto m = parseMediumJson(text, "bad.json");
  ASSERT_FALSE(m.ok()) << text;
  EXPECT_NE(m.error().message.find("bad.json"), std::string::npos) << m.error().message;
  EXPECT_NE(m.error().message.find(key), std::string::npos) << m.error().message;
  EXPECT_EQ(m.error().message.find('\n'), std::string::npos);
}

TEST(Medium, BadFilesGiveErrorsNamingTheKey) {
  const std::string layer = R"("n": 1.4, "mua": 0.1, "mus": 9.9, "g": 0.9)";
  expectError(R"({"ambient_n": 1.0, "layers": [{)" + layer + R"(, "thickness": "inf", "musp": 1}]})",
              "'layers[0].musp'");
  expectError(R"({"ambient_n": 1.0, "layers": [{"n": 1.4, "mus": 9.9, "g": 0.9, "thickness": 1}]})",
              "'layers[0].mua'");
  expectError(R"({"ambient_n": 1.0, "layers": [{)" + layer + R"(, "thickness": "infinite"}]})",
              "'layers[0].thickness'");
  expectError(R"({"ambient_n": 1.0, "layers": [{)" + layer + R"(, "thickness": -1}]})",
              "'layers[0].thickness'");
  expectError(
      R"({"ambient_n": 1.0, "layers": [{"n": 1.4, "mua": 0.1, "mus": 9.9, "g": 1.2, "thickness": 1}]})",
      "'layers[0].g'");
  expectError(R"({"ambient_n": "one", "layers": []})", "'ambient_n'");
  expectError(R"({"ambient": 1.0, "layers": []})", "'ambient'");
  expectError(R"({"ambient_n": 1.0, "layers": []})", "'layers'");
  expectError(R"({"ambient_n": 1.0, "layers": [{)" + layer + R"(, "thickness": "inf"}, {)" + layer +
                  R"(, "thickness": 1}]})",
              "'layers[0].thickness'");
  expectError(R"({"ambient_n": 1.0, )", "not valid JSON");
  auto missing = loadMediumFile("/nonexistent/medium.json");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().message.find("/nonexistent/medium.json"), std::string::npos);
}

}  // namespace
}  // namespace tissue::optics
