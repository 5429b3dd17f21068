// The Embree back end when tissue is built without Embree: one clear Error.
#include "embree_mesh.h"

namespace tissue::truth::detail {

bool embreeBuiltIn() {
  return false;
}

Result<std::unique_ptr<RayMesh>> makeEmbreeMesh(std::span<const Float3>, std::span<const Triangle>) {
  return Error{
      "ray mesh: this tissue was built without Embree; install it (Debian/Ubuntu: libembree-dev) "
      "and reconfigure, or use Intersector::Bvh"};
}

}  // namespace tissue::truth::detail
