#include "dymesh/accel/embree_locator.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace dymesh {
namespace {

// a hit this far (barycentric) from every edge of its triangle is inside it for sure: the float
// triangle is inflated by far less than this fraction of any reasonable triangle
constexpr float kSurelyInside = 0.05f;

RTCDevice Dev(const EmbreeDevice& d) { return static_cast<RTCDevice>(d.handle()); }

// ray context that collects every hit of the segment instead of keeping the closest
struct CollectContext {
  RTCIntersectContext base;
  std::vector<Candidate>* out;
  const EmbreeLocator* locator;
};

void CollectAllHits(const RTCFilterFunctionNArguments* args) {
  // record the triangle (and whether the hit is clear of its edges), then reject the hit so that
  // traversal goes on along the whole segment
  auto* ctx = reinterpret_cast<const CollectContext*>(args->context);
  if (args->valid[0] == 0) return;
  const float u = RTCHitN_u(args->hit, args->N, 0), v = RTCHitN_v(args->hit, args->N, 0);
  const bool inside = std::min({u, v, 1.0f - u - v}) >= kSurelyInside;
  ctx->out->push_back({static_cast<int>(RTCHitN_primID(args->hit, args->N, 0)), inside});
  args->valid[0] = 0;
}

bool CollectNearPrimitive(RTCPointQueryFunctionArguments* args) {
  // every triangle in a leaf the query sphere reaches; the contact step tests it exactly
  static_cast<std::vector<Candidate>*>(args->userPtr)->push_back({static_cast<int>(args->primID), false});
  return false;
}

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
  // inflation: four float ulps at the mesh's largest coordinate
  double radius = 0.0;
  for (const Vec3& p : mesh.vertices) radius = std::max(radius, p.cwiseAbs().maxCoeff());
  inflation_ = 4.0 * std::max(radius, 1.0) * std::ldexp(1.0, -23);
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
  // the float surface sits `inflation_` outside the double one (along the vertex normals), so a
  // segment through a silhouette edge in double still meets the float triangle
  std::vector<Vec3> normal(vertex_count_, Vec3::Zero());
  for (const auto& t : triangles_) {
    const Vec3 n = TriangleCross(vertices[t[0]], vertices[t[1]], vertices[t[2]]);
    for (int v : t) normal[v] += n;
  }
  for (size_t v = 0; v < vertex_count_; ++v) {
    const double len = normal[v].norm();
    const Vec3 p = len > 0.0 ? Vec3(vertices[v] + (inflation_ / len) * normal[v]) : vertices[v];
    for (int k = 0; k < 3; ++k) vertex_buffer_[3 * v + k] = static_cast<float>(p[k]);
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

void EmbreeLocator::TrianglesAlongSegment(int /*key*/, const Vec3& origin, const Vec3& dir, double length,
                                          std::vector<Candidate>* out) const {
  // one ray over the segment, stretched a little at both ends (the exact test trims it again)
  const double slack = 1e-4 * (1.0 + length);
  const Vec3 o = origin - slack * dir;
  CollectContext ctx;
  rtcInitIntersectContext(&ctx.base);
  ctx.base.filter = CollectAllHits;
  ctx.out = out;
  ctx.locator = this;
  RTCRayHit rh;
  std::memset(&rh, 0, sizeof(rh));
  rh.ray.org_x = static_cast<float>(o.x());
  rh.ray.org_y = static_cast<float>(o.y());
  rh.ray.org_z = static_cast<float>(o.z());
  rh.ray.dir_x = static_cast<float>(dir.x());
  rh.ray.dir_y = static_cast<float>(dir.y());
  rh.ray.dir_z = static_cast<float>(dir.z());
  rh.ray.tnear = 0.0f;
  rh.ray.tfar = static_cast<float>(length + 2.0 * slack);
  rh.ray.mask = 0xFFFFFFFFu;  // Debian's Embree is built with ray masks
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  const size_t first = out->size();
  rtcIntersect1(static_cast<RTCScene>(scene_), &ctx.base, &rh);
  // a hit near an edge or vertex may name the neighbour of the triangle the exact test accepts:
  // the triangles around its corners are candidates too
  const size_t hits_end = out->size();
  for (size_t i = first; i < hits_end; ++i) {
    if ((*out)[i].inside) continue;
    for (int corner : triangles_[(*out)[i].triangle]) {
      for (int k = ring_.offsets[corner]; k < ring_.offsets[corner + 1]; ++k) out->push_back({ring_.ids[k], false});
    }
  }
}

void EmbreeLocator::TrianglesNearPoint(int /*key*/, const Vec3& p, double radius, std::vector<Candidate>* out) const {
  RTCPointQuery query;
  query.x = static_cast<float>(p.x());
  query.y = static_cast<float>(p.y());
  query.z = static_cast<float>(p.z());
  query.time = 0.0f;
  query.radius = static_cast<float>(radius * (1.0 + 1e-4) + inflation_ + 1e-6);
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(static_cast<RTCScene>(scene_), &query, &context, CollectNearPrimitive, out);
}

LocatorFactory MakeEmbreeLocatorFactory(std::shared_ptr<const EmbreeDevice> device) {
  return [device](const TriMesh& mesh) { return std::make_unique<EmbreeLocator>(device, mesh); };
}

}  // namespace dymesh
