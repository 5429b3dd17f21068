// The Embree 3 adapter: the only file that includes Embree (rtcore.h). One device and one scene
// with one triangle geometry; nearest-hit queries through rtcIntersect1 and nearest-point queries
// through rtcPointQuery, both thread safe on a committed scene.
#include "embree_mesh.h"

#include <glm/glm.hpp>

#include <embree3/rtcore.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "depth_tree.h"

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
  EmbreeMesh(RTCDevice device, RTCScene scene, std::span<const Float3> positions,
             std::span<const Triangle> triangles)
      : m_device(device), m_scene(scene), m_triangles(triangles.begin(), triangles.end()) {
    for (const Float3& p : positions)
      m_positions.emplace_back(p.x, p.y, p.z);
  }
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
  // rtcPointQuery walks Embree's hierarchy with a sphere that shrinks as triangles come closer;
  // the distances themselves are computed here in double precision.
  std::optional<SurfacePoint> nearest(const std::array<double, 3>& p, double maxDistanceMm) const override {
    PointQuery data{this, {p[0], p[1], p[2]}, maxDistanceMm * maxDistanceMm, {}, false};
    RTCPointQuery query;
    query.x = float(p[0]);
    query.y = float(p[1]);
    query.z = float(p[2]);
    query.time = 0.0f;
    query.radius = float(maxDistanceMm) * (1.0f + 1e-6f);
    RTCPointQueryContext context;
    rtcInitPointQueryContext(&context);
    rtcPointQuery(m_scene, &query, &context, &EmbreeMesh::visit, &data);
    if (!data.found) return std::nullopt;
    data.best.distanceMm = std::sqrt(data.best2);
    return data.best;
  }
  Intersector kind() const override { return Intersector::Embree; }

 private:
  struct PointQuery {
    const EmbreeMesh* self;
    glm::dvec3 p;
    double best2;
    SurfacePoint best;
    bool found;
  };
  // Called for each triangle whose bounds meet the query sphere; true when it shrinks the sphere.
  static bool visit(RTCPointQueryFunctionArguments* args) {
    auto* data = static_cast<PointQuery*>(args->userPtr);
    const EmbreeMesh& m = *data->self;
    const Triangle& t = m.m_triangles[args->primID];
    const glm::dvec3 &a = m.m_positions[t[0]], &b = m.m_positions[t[1]], &c = m.m_positions[t[2]];
    const glm::dvec2 w = closestOnTriangle(data->p, a, b, c);
    const glm::dvec3 q = a + w.x * (b - a) + w.y * (c - a);
    const double d2 = glm::dot(q - data->p, q - data->p);
    if (d2 >= data->best2) return false;
    data->best2 = d2;
    data->best = {0.0, args->primID, w.x, w.y};
    data->found = true;
    args->query->radius = float(std::sqrt(d2)) * (1.0f + 1e-6f);
    return true;
  }

  RTCDevice m_device;
  RTCScene m_scene;
  std::vector<glm::dvec3> m_positions;
  std::vector<Triangle> m_triangles;
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
  return std::unique_ptr<RayMesh>(new EmbreeMesh(device, scene, positions, triangles));
}

}  // namespace tissue::truth::detail
