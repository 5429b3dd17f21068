#include "tissue/render/shading.h"

namespace tissue::render {

std::string_view shadingMethodName(ShadingMethod method) {
  switch (method) {
    case ShadingMethod::Lit:
      return "lit";
    case ShadingMethod::Separable:
      return "separable";
    case ShadingMethod::TextureSpace:
      return "texture-space";
    case ShadingMethod::RayMarch:
      return "ray-march";
    case ShadingMethod::Parallax:
      return "parallax";
  }
  return "unknown";
}

}  // namespace tissue::render
