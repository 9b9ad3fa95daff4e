#include "dymesh/accel/embree_locator.h"

#include <embree3/rtcore.h>

#include <cmath>
#include <cstring>
#include <stdexcept>

namespace dymesh {
namespace {

RTCDevice Dev(const EmbreeDevice& d) { return static_cast<RTCDevice>(d.handle()); }

// ray context that collects every hit of the segment instead of keeping the closest
struct CollectContext {
  RTCIntersectContext base;
  std::vector<int>* out;
};

void CollectAllHits(const RTCFilterFunctionNArguments* args) {
  // record the triangle, then reject the hit so traversal goes on along the whole segment
  auto* ctx = reinterpret_cast<const CollectContext*>(args->context);
  if (args->valid[0] == 0) return;
  ctx->out->push_back(static_cast<int>(RTCHitN_primID(args->hit, args->N, 0)));
  args->valid[0] = 0;
}

bool CollectNearPrimitive(RTCPointQueryFunctionArguments* args) {
  // every triangle in a leaf the query sphere reaches; the contact step tests it exactly
  static_cast<std::vector<int>*>(args->userPtr)->push_back(static_cast<int>(args->primID));
  return false;
}

constexpr double kEdgeOffset = 1e-5;  // [m] offset of the retry rays, ~30 float ulps at 5 m

std::string DefaultConfig() {
  // determinism: a pinned ISA, so BVH layout and hits do not depend on the machine's vector width
  return __builtin_cpu_supports("avx2") ? "isa=avx2" : "isa=sse4.2";
}

}  // namespace

EmbreeDevice::EmbreeDevice(const std::string& config) {
  const std::string cfg = config.empty() ? DefaultConfig() : config;
  device_ = rtcNewDevice(cfg.c_str());
  if (!device_) throw std::runtime_error("embree: cannot create device with config '" + cfg + "'");
}

EmbreeDevice::~EmbreeDevice() { rtcReleaseDevice(static_cast<RTCDevice>(device_)); }

EmbreeLocator::EmbreeLocator(std::shared_ptr<const EmbreeDevice> device, const TriMesh& mesh)
    : device_(std::move(device)), vertex_count_(mesh.vertices.size()), triangles_(mesh.triangles),
      ring_(BuildVertexTriangles(mesh)) {
  // a deformable scene: DYNAMIC + LOW quality so Update refits, ROBUST so shared edges do not leak
  RTCScene scene = rtcNewScene(Dev(*device_));
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_DYNAMIC | RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
  rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_LOW);
  RTCGeometry geom = rtcNewGeometry(Dev(*device_), RTC_GEOMETRY_TYPE_TRIANGLE);
  rtcSetGeometryBuildQuality(geom, RTC_BUILD_QUALITY_REFIT);
  // Embree-allocated buffers carry the padding its 16-byte vertex loads need
  vertex_buffer_ = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                               3 * sizeof(float), vertex_count_));
  auto* index = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                               3 * sizeof(unsigned), triangles_.size()));
  for (size_t t = 0; t < triangles_.size(); ++t) {
    for (int k = 0; k < 3; ++k) index[3 * t + k] = static_cast<unsigned>(triangles_[t][k]);
  }
  scene_ = scene;
  geometry_ = geom;
  CopyVertices(mesh.vertices);
  rtcCommitGeometry(geom);
  rtcAttachGeometry(scene, geom);
  rtcCommitScene(scene);
}

EmbreeLocator::~EmbreeLocator() {
  rtcReleaseGeometry(static_cast<RTCGeometry>(geometry_));
  rtcReleaseScene(static_cast<RTCScene>(scene_));
}

void EmbreeLocator::CopyVertices(const std::vector<Vec3>& vertices) {
  for (size_t v = 0; v < vertex_count_; ++v) {
    for (int k = 0; k < 3; ++k) vertex_buffer_[3 * v + k] = static_cast<float>(vertices[v][k]);
  }
}

void EmbreeLocator::Update(const std::vector<Vec3>& vertices) {
  // refit: new float vertices, then update buffer, commit geometry and scene
  CopyVertices(vertices);
  auto geom = static_cast<RTCGeometry>(geometry_);
  rtcUpdateGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0);
  rtcCommitGeometry(geom);
  rtcCommitScene(static_cast<RTCScene>(scene_));
}

void EmbreeLocator::CollectAlongSegment(const Vec3& origin, const Vec3& dir, double length,
                                        std::vector<int>* out) const {
  CollectContext ctx;
  rtcInitIntersectContext(&ctx.base);
  ctx.base.filter = CollectAllHits;
  ctx.out = out;
  RTCRayHit rh;
  std::memset(&rh, 0, sizeof(rh));
  rh.ray.org_x = static_cast<float>(origin.x());
  rh.ray.org_y = static_cast<float>(origin.y());
  rh.ray.org_z = static_cast<float>(origin.z());
  rh.ray.dir_x = static_cast<float>(dir.x());
  rh.ray.dir_y = static_cast<float>(dir.y());
  rh.ray.dir_z = static_cast<float>(dir.z());
  rh.ray.tnear = 0.0f;
  rh.ray.tfar = static_cast<float>(length);
  rh.ray.mask = 0xFFFFFFFFu;  // Debian's Embree is built with ray masks
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(static_cast<RTCScene>(scene_), &ctx.base, &rh);
}

void EmbreeLocator::TrianglesAlongSegment(int /*key*/, const Vec3& origin, const Vec3& dir, double length,
                                          std::vector<int>* out) const {
  // the float segment is stretched a little at both ends; the exact test trims it again
  const double slack = 1e-4 * (1.0 + length);
  const size_t before = out->size();
  CollectAlongSegment(origin - slack * dir, dir, length + 2.0 * slack, out);
  // a ray exactly along a silhouette edge or through a vertex can fall between a face and its
  // neighbour seen edge-on: six parallel rays offset 10 um at 60 degrees reach the face
  if (out->size() == before) {
    const Vec3 u = dir.unitOrthogonal(), w = dir.cross(u);
    for (int k = 0; k < 6; ++k) {
      const double angle = 1.0471975511965976 * k;
      const Vec3 offset = kEdgeOffset * (std::cos(angle) * u + std::sin(angle) * w);
      CollectAlongSegment(origin - slack * dir + offset, dir, length + 2.0 * slack, out);
    }
  }
  // a float hit on an edge or vertex may name the neighbour of the triangle the exact test
  // accepts: every triangle sharing a vertex with a hit is a candidate too
  const size_t hits_end = out->size();
  for (size_t i = before; i < hits_end; ++i) {
    for (int corner : triangles_[(*out)[i]]) {
      out->insert(out->end(), ring_.ids.begin() + ring_.offsets[corner], ring_.ids.begin() + ring_.offsets[corner + 1]);
    }
  }
}

void EmbreeLocator::TrianglesNearPoint(int /*key*/, const Vec3& p, double radius, std::vector<int>* out) const {
  RTCPointQuery query;
  query.x = static_cast<float>(p.x());
  query.y = static_cast<float>(p.y());
  query.z = static_cast<float>(p.z());
  query.time = 0.0f;
  query.radius = static_cast<float>(radius * (1.0 + 1e-4) + 1e-6);
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(static_cast<RTCScene>(scene_), &query, &context, CollectNearPrimitive, out);
}

LocatorFactory MakeEmbreeLocatorFactory(std::shared_ptr<const EmbreeDevice> device) {
  return [device](const TriMesh& mesh) { return std::make_unique<EmbreeLocator>(device, mesh); };
}

}  // namespace dymesh
