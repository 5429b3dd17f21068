// The Embree 3 adapter: the only file that includes Embree (rtcore.h). One device and one scene
// with one triangle geometry; nearest-hit queries through rtcIntersect1, which is thread safe on a
// committed scene.
#include "embree_mesh.h"

#include <embree3/rtcore.h>

#include <cmath>
#include <limits>
#include <string>

namespace tissue::truth::detail {
namespace {

std::string deviceError(RTCDevice device) {
  switch (rtcGetDeviceError(device)) {
    case RTC_ERROR_NONE:
      return "no error";
    case RTC_ERROR_INVALID_ARGUMENT:
      return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION:
      return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY:
      return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU:
      return "unsupported CPU";
    case RTC_ERROR_CANCELLED:
      return "cancelled";
    default:
      return "unknown error";
  }
}

class EmbreeMesh final : public RayMesh {
 public:
  EmbreeMesh(RTCDevice device, RTCScene scene) : m_device(device), m_scene(scene) {}
  ~EmbreeMesh() override {
    rtcReleaseScene(m_scene);
    rtcReleaseDevice(m_device);
  }
  EmbreeMesh(const EmbreeMesh&) = delete;
  EmbreeMesh& operator=(const EmbreeMesh&) = delete;

  std::optional<MeshHit> intersect(const std::array<double, 3>& o, const std::array<double, 3>& d,
                                   double tMin, double tMax) const override {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh{};
    rh.ray.org_x = float(o[0]);
    rh.ray.org_y = float(o[1]);
    rh.ray.org_z = float(o[2]);
    rh.ray.dir_x = float(d[0]);
    rh.ray.dir_y = float(d[1]);
    rh.ray.dir_z = float(d[2]);
    rh.ray.tnear = float(tMin);
    rh.ray.tfar = tMax < double(std::numeric_limits<float>::max()) ? float(tMax)
                                                                   : std::numeric_limits<float>::infinity();
    rh.ray.mask = 0xFFFFFFFFu;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(m_scene, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    // Embree's u, v weigh the second and third vertex, as MeshHit's b1, b2.
    return MeshHit{double(rh.ray.tfar), rh.hit.primID, double(rh.hit.u), double(rh.hit.v)};
  }
  Intersector kind() const override { return Intersector::Embree; }

 private:
  RTCDevice m_device;
  RTCScene m_scene;
};

}  // namespace

bool embreeBuiltIn() {
  return true;
}

Result<std::unique_ptr<RayMesh>> makeEmbreeMesh(std::span<const Float3> positions,
                                                std::span<const Triangle> triangles) {
  RTCDevice device = rtcNewDevice(nullptr);
  if (!device) return Error{"ray mesh: Embree could not create a device (" + deviceError(nullptr) + ")"};
  RTCScene scene = rtcNewScene(device);
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), positions.size()));
  auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), triangles.size()));
  if (!vertices || !indices) {
    const std::string why = deviceError(device);
    rtcReleaseGeometry(geometry);
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
    return Error{"ray mesh: Embree could not allocate the mesh buffers (" + why + ")"};
  }
  for (std::size_t i = 0; i < positions.size(); ++i) {
    vertices[3 * i + 0] = positions[i].x;
    vertices[3 * i + 1] = positions[i].y;
    vertices[3 * i + 2] = positions[i].z;
  }
  for (std::size_t i = 0; i < triangles.size(); ++i)
    for (int k = 0; k < 3; ++k)
      indices[3 * i + std::size_t(k)] = triangles[i][std::size_t(k)];
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(scene);
  if (rtcGetDeviceError(device) != RTC_ERROR_NONE) {
    const std::string why = deviceError(device);
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
    return Error{"ray mesh: Embree could not build the scene (" + why + ")"};
  }
  return std::unique_ptr<RayMesh>(new EmbreeMesh(device, scene));
}

}  // namespace tissue::truth::detail
