#include "ray_march.h"

namespace tissue::render {

Result<RayMarchMethod> RayMarchMethod::create(const gl::GlApi&, const gl::ShaderLibrary&) {
  return RayMarchMethod{};
}

Result<void> RayMarchMethod::draw(const FrameContext&, std::span<const ObjectDraw>) const {
  return Error{
      "renderer: shading method 'ray-march' is not implemented in this build (it arrives with branch "
      "raymarch)"};
}

}  // namespace tissue::render
