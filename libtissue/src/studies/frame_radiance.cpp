// The last frame's linear radiance (frame_radiance.h).
#include "tissue/studies/frame_radiance.h"

namespace tissue::studies {

Result<std::vector<Float3>> lastFrameRadiance(render::Renderer& renderer) {
  auto radiance = renderer.readFrame(render::FrameView::Radiance);
  if (!radiance) return radiance.error();
  auto blurred = renderer.readFrame(render::FrameView::BlurredDiffuse);
  if (!blurred) return blurred.error();
  std::vector<Float3> out(radiance->pixels.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    const Float4 r = radiance->pixels[i], d = blurred->pixels[i];
    out[i] = {r.x + d.x, r.y + d.y, r.z + d.z};
  }
  return out;
}

}  // namespace tissue::studies
