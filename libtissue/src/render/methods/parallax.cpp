#include "parallax.h"

namespace tissue::render {

Result<ParallaxMethod> ParallaxMethod::create(const gl::GlApi&, const gl::ShaderLibrary&) {
  return ParallaxMethod{};
}

Result<void> ParallaxMethod::draw(const FrameContext&, std::span<const ObjectDraw>) const {
  return Error{
      "renderer: shading method 'parallax' is not implemented in this build (it arrives with branch "
      "raymarch)"};
}

}  // namespace tissue::render
