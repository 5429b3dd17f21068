// gl::countLiveObjects, the soak run's leak check: it counts what GL says is alive, so an object
// made and bound shows up, and deleting it takes it away again.
#include "gl_test_support.h"
#include "tissue/context/headless_context.h"
#include "tissue/gl/gl_api.h"
#include "tissue/gl/objects.h"

namespace tissue::test {
namespace {

TEST(ObjectCensus, CountsWhatIsBoundAndForgetsWhatIsDeleted) {
  TISSUE_CONTEXT_OR_FAIL(context, Backend::Egl);
  ASSERT_TRUE(context->makeCurrent());
  auto loaded = gl::loadGl(context->procAddressFunction());
  ASSERT_TRUE(loaded) << loaded.error().message;
  const gl::GlApi& gl = **loaded;
  const gl::ObjectCensus before = gl::countLiveObjects(gl);
  {
    auto texture = gl::Texture::create(gl);
    auto buffer = gl::Buffer::create(gl);
    auto program = gl::Program::create(gl);
    gl.BindTexture(GL_TEXTURE_2D, texture.id());  // a name becomes an object when first bound
    gl.BindBuffer(GL_ARRAY_BUFFER, buffer.id());
    const gl::ObjectCensus during = gl::countLiveObjects(gl);
    EXPECT_EQ(during.textures, before.textures + 1);
    EXPECT_EQ(during.buffers, before.buffers + 1);
    EXPECT_EQ(during.programs, before.programs + 1);  // glCreateProgram makes the object at once
    EXPECT_EQ(during.total(), before.total() + 3);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    gl.BindBuffer(GL_ARRAY_BUFFER, 0);
  }
  EXPECT_EQ(gl::countLiveObjects(gl), before);
}

}  // namespace
}  // namespace tissue::test
