#include "separable_sss.h"

namespace tissue::render {

Result<SeparableMethod> SeparableMethod::create(const gl::GlApi&, const gl::ShaderLibrary&) {
  return SeparableMethod{};
}

Result<void> SeparableMethod::draw(const FrameContext&, std::span<const ObjectDraw>) const {
  return Error{
      "renderer: shading method 'separable' is not implemented in this build (it arrives with branch sss)"};
}

Result<void> SeparableMethod::post(const FrameContext&, std::span<const ObjectDraw>) const {
  return {};
}

}  // namespace tissue::render
