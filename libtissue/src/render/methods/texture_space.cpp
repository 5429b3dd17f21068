#include "texture_space.h"

namespace tissue::render {

Result<TextureSpaceMethod> TextureSpaceMethod::create(const gl::GlApi&, const gl::ShaderLibrary&) {
  return TextureSpaceMethod{};
}

Result<void> TextureSpaceMethod::draw(const FrameContext&, std::span<const ObjectDraw>) const {
  return Error{
      "renderer: shading method 'texture-space' is not implemented in this build (it arrives with branch "
      "tsd)"};
}

}  // namespace tissue::render
