// Shader library: embedded sources, override folder, #define injection, includes, errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "gl_test_support.h"
#include "tissue/gl/program.h"
#include "tissue/gl/shader_library.h"

namespace tissue::test {
namespace {

gl::ShaderLibrary embeddedOnly() {
  return gl::ShaderLibrary({.overrideDir = {}});
}

std::filesystem::path scratchDir(const std::string& name) {
  const auto dir = std::filesystem::path(TISSUE_TEST_OUTPUT_DIR) / "shaders" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "common");
  return dir;
}

void writeFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

TEST(ShaderLibraryTest, EmbedsTheShaderFolder) {
  auto lit = embeddedOnly().source("lit/lit.frag");
  ASSERT_TRUE(lit) << lit.error().message;
  EXPECT_EQ(lit->rfind("#version 330 core", 0), 0u);
  EXPECT_TRUE(embeddedOnly().source("common/tonemap.glsl"));
  auto missing = embeddedOnly().source("nope.frag");
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().message.find("nope.frag"), std::string::npos);
}

TEST(ShaderLibraryTest, InjectsDefinesRightAfterVersionAndResolvesIncludes) {
  const gl::ShaderDefine defines[] = {{"TISSUE_NORMAL_MAP", "1"}, {"TISSUE_TEST_FLAG", ""}};
  auto shader = embeddedOnly().preprocess("lit/lit.frag", defines);
  ASSERT_TRUE(shader) << shader.error().message;
  const std::string& s = shader->source;
  EXPECT_EQ(s.rfind("#version 330 core\n#define TISSUE_NORMAL_MAP 1\n#define TISSUE_TEST_FLAG \n", 0), 0u)
      << s;
  EXPECT_EQ(s.find("#include"), std::string::npos);
  EXPECT_NE(s.find("vec3 perturbNormal("), std::string::npos);
  EXPECT_NE(s.find("vec3 tonemapReinhard("), std::string::npos);
  ASSERT_EQ(shader->files.size(), 8u);  // lit.frag and 7 included, each once
  EXPECT_NE(std::find(shader->files.begin(), shader->files.end(), "common/specular.glsl"),
            shader->files.end());
  EXPECT_EQ(shader->files[0], "lit/lit.frag");
  EXPECT_EQ(shader->files[1], "common/surface.glsl");
  EXPECT_EQ(shader->files[2], "common/normal_mapping.glsl");
}

TEST(ShaderLibraryTest, OverrideFolderWinsAndIncludesOnce) {
  const auto dir = scratchDir("override");
  writeFile(dir / "common/a.glsl", "float a() { return 1.0; }\n");
  writeFile(dir / "x.frag",
            "#version 330 core\n#include \"common/a.glsl\"\n#include \"common/a.glsl\"\nvoid main() {}\n");
  const gl::ShaderLibrary library({.overrideDir = dir});
  auto shader = library.preprocess("x.frag");
  ASSERT_TRUE(shader) << shader.error().message;
  const std::string& s = shader->source;
  EXPECT_NE(s.find("float a()"), std::string::npos);
  EXPECT_EQ(s.find("float a()"), s.rfind("float a()")) << "included twice:\n" << s;
  // Files the override folder lacks still come from the embedded copy.
  EXPECT_TRUE(library.source("common/surface.vert"));
}

TEST(ShaderLibraryTest, MissingIncludeNamesFileAndLine) {
  const auto dir = scratchDir("missing_include");
  writeFile(dir / "y.frag", "#version 330 core\n\n#include \"common/absent.glsl\"\nvoid main() {}\n");
  auto shader = gl::ShaderLibrary({.overrideDir = dir}).preprocess("y.frag");
  ASSERT_FALSE(shader);
  EXPECT_NE(shader.error().message.find("common/absent.glsl"), std::string::npos) << shader.error().message;
  EXPECT_NE(shader.error().message.find("y.frag:3"), std::string::npos) << shader.error().message;
}

TEST(ShaderLibraryTest, MissingVersionIsAnError) {
  const auto dir = scratchDir("no_version");
  writeFile(dir / "z.frag", "void main() {}\n");
  auto shader = gl::ShaderLibrary({.overrideDir = dir}).preprocess("z.frag");
  ASSERT_FALSE(shader);
  EXPECT_NE(shader.error().message.find("#version"), std::string::npos);
}

class ShaderCompileTest : public ::testing::TestWithParam<Backend> {};

TEST_P(ShaderCompileTest, EmbeddedVariantsCompile) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto gl = gl::loadGl(context->procAddressFunction());
  ASSERT_TRUE(gl) << gl.error().message;
  const gl::ShaderDefine mapped[] = {{"TISSUE_NORMAL_MAP", "1"}};
  EXPECT_TRUE(gl::buildProgram(**gl, embeddedOnly(), {"common/surface.vert", "lit/lit.frag", {}}));
  auto program = gl::buildProgram(**gl, embeddedOnly(), {"common/surface.vert", "lit/lit.frag", mapped});
  ASSERT_TRUE(program) << program.error().message;
  EXPECT_TRUE(program->owned());
}

TEST_P(ShaderCompileTest, BrokenShaderGivesErrorWithFileNameAndLog) {
  TISSUE_CONTEXT_OR_FAIL(context, GetParam());
  auto gl = gl::loadGl(context->procAddressFunction());
  ASSERT_TRUE(gl) << gl.error().message;
  const auto dir = scratchDir(std::string("broken_") + backendName(GetParam()));
  writeFile(dir / "broken.frag",
            "#version 330 core\n#include \"common/tonemap.glsl\"\nout vec4 c;\nvoid main() { c = "
            "undefinedThing; }\n");
  const gl::ShaderLibrary library({.overrideDir = dir});
  auto program = gl::buildProgram(**gl, library, {"common/surface.vert", "broken.frag", {}});
  ASSERT_FALSE(program);
  const std::string& message = program.error().message;
  EXPECT_NE(message.find("broken.frag"), std::string::npos) << message;
  EXPECT_NE(message.find("undefinedThing"), std::string::npos) << message;  // the driver's log
  // Line 4 of broken.frag, source string 0, survives the injected include thanks to #line.
  // (Mesa writes "0:4(..)", NVIDIA "0(4)").
  EXPECT_TRUE(message.find("0:4") != std::string::npos || message.find("0(4)") != std::string::npos)
      << message;
}

INSTANTIATE_TEST_SUITE_P(Backends, ShaderCompileTest, ::testing::Values(Backend::Egl, Backend::OsMesa),
                         backendParamName);

}  // namespace
}  // namespace tissue::test
