#include "dymesh/accel/embree_locator.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "dymesh/core/parallel.h"

namespace dymesh::accel {
namespace {

// a hit this many inflations away from every edge of its inflated triangle is inside the double
// triangle for sure (float rounding and the inflation together stay below two inflations); the
// growth below is added on top
constexpr double kInsideMargin = 8.0;

// each float triangle is also grown in its plane until its edges stand this many inflations outside
// the inflated ones (more than the inflation can pull an edge in, plus rounding)...
constexpr double kGrowth = 2.0;
// ...but no corner moves more than this many inflations (a needle's tip would run off)
constexpr double kMaxCornerShift = 64.0;

// triangles per Embree geometry on a large mesh: a crush refits only the groups it touches
constexpr size_t kGroupSize = 4096;
// up to this many triangles a mesh is one geometry. Measured (Embree 3.13, 2 cores, 2026-11-23): a
// scene of three or more geometries pays ~0.4 ms per commit whatever their size, while one geometry
// of 8k triangles refits in ~70 us; on a million triangles the groups win
constexpr size_t kSingleGeometryLimit = 65536;

RTCDevice Dev(const EmbreeDevice& d) { return static_cast<RTCDevice>(d.handle()); }

// ray context that collects every hit of the segment instead of keeping the closest
struct CollectContext {
  RTCIntersectContext base;
  std::vector<Candidate>* out;
  const EmbreeLocator* locator;
  double ray_length;  // the float ray direction's length (taken once per ray, not per hit)
};

// |cos| of the angle between the ray and the hit face's normal (0 for a degenerate face)
double RayFaceCosine(const RTCFilterFunctionNArguments* args, double ray_length) {
  const Vec3 ng(RTCHitN_Ng_x(args->hit, args->N, 0), RTCHitN_Ng_y(args->hit, args->N, 0),
                RTCHitN_Ng_z(args->hit, args->N, 0));
  const Vec3 dir(RTCRayN_dir_x(args->ray, args->N, 0), RTCRayN_dir_y(args->ray, args->N, 0),
                 RTCRayN_dir_z(args->ray, args->N, 0));
  const double lengths = ng.norm() * ray_length;
  return lengths > 0.0 ? std::abs(ng.dot(dir)) / lengths : 0.0;
}

void CollectAllHits(const RTCFilterFunctionNArguments* args) {
  // record the triangle (and whether the hit is clear of its edges), then reject the hit so that
  // traversal goes on along the whole segment
  auto* ctx = reinterpret_cast<const CollectContext*>(args->context);
  if (args->valid[0] == 0) return;
  const float u = RTCHitN_u(args->hit, args->N, 0), v = RTCHitN_v(args->hit, args->N, 0);
  const int triangle = ctx->locator->Triangle(RTCHitN_geomID(args->hit, args->N, 0), RTCHitN_primID(args->hit, args->N, 0));
  // a float hit's error along the face grows as 1 / cos of the angle between the ray and the face
  // normal: a ray grazing a face (seen at 89.5 degrees on a car's flat side) landed on the neighbour
  // of the face the double test crosses, trusted as clear of its edges. Clear means the edge margin
  // over that cosine
  const double clearance = std::min({u, v, 1.0f - u - v}) * RayFaceCosine(args, ctx->ray_length);
  ctx->out->push_back({triangle, clearance >= ctx->locator->EdgeMargin(triangle)});
  args->valid[0] = 0;
}

// user data of a point query
struct NearContext {
  std::vector<Candidate>* out;
  const EmbreeLocator* locator;
};

bool CollectNearPrimitive(RTCPointQueryFunctionArguments* args) {
  // every triangle in a leaf the query sphere reaches; the contact step tests it exactly
  auto* ctx = static_cast<NearContext*>(args->userPtr);
  ctx->out->push_back({ctx->locator->Triangle(args->geomID, args->primID), false});
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

namespace {

// Morton code of a point in the unit cube (10 bits per axis)
std::uint32_t Morton(const Vec3& unit) {
  auto spread = [](std::uint32_t x) {
    x = (x | (x << 16)) & 0x030000FF;
    x = (x | (x << 8)) & 0x0300F00F;
    x = (x | (x << 4)) & 0x030C30C3;
    return (x | (x << 2)) & 0x09249249;
  };
  auto cell = [](double c) { return static_cast<std::uint32_t>(std::clamp(c, 0.0, 1.0) * 1023.0); };
  return spread(cell(unit.x())) | (spread(cell(unit.y())) << 1) | (spread(cell(unit.z())) << 2);
}

}  // namespace

EmbreeLocator::EmbreeLocator(std::shared_ptr<const EmbreeDevice> device, const TriMesh& mesh)
    : device_(std::move(device)), triangles_(mesh.triangles), ring_(BuildVertexTriangles(mesh)) {
  const size_t nv = mesh.vertices.size(), nt = triangles_.size();
  // inflation: four float ulps at the mesh's largest coordinate
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (const Vec3& p : mesh.vertices) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  inflation_ = 4.0 * std::max({lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff(), 1.0}) * std::ldexp(1.0, -23);
  // inflated vertices
  inflated_.resize(nv);
  affected_.assign(nv, 0);
  LinkTwins(mesh.vertices);
  for (size_t v = 0; v < nv; ++v) InflateVertex(mesh.vertices, static_cast<int>(v));
  // groups: triangles in Morton order of their centres, cut into runs of kGroupSize (a small mesh: one run)
  const size_t group_size = nt <= kSingleGeometryLimit ? std::max<size_t>(nt, 1) : kGroupSize;
  std::vector<std::pair<std::uint32_t, int>> order(nt);
  const Vec3 extent = (hi - lo).cwiseMax(Vec3::Constant(1e-9));
  for (size_t t = 0; t < nt; ++t) {
    const Vec3 centre = (mesh.vertices[triangles_[t][0]] + mesh.vertices[triangles_[t][1]] +
                         mesh.vertices[triangles_[t][2]]) / 3.0;
    order[t] = {Morton((centre - lo).cwiseQuotient(extent)), static_cast<int>(t)};
  }
  std::sort(order.begin(), order.end());
  group_triangles_.resize(nt);
  if (group_size < nt) triangle_slot_.resize(nt);  // a single group needs no table
  for (size_t i = 0; i < nt; ++i) {
    group_triangles_[i] = order[i].second;
    if (group_size < nt) triangle_slot_[order[i].second] = static_cast<int>(i);
  }
  for (size_t first = 0; first < nt; first += group_size) group_first_.push_back(static_cast<int>(first));
  group_first_.push_back(static_cast<int>(nt));
  // float corners, three per triangle in its group's slot, each triangle grown with its edge margin
  // (padded so the last corner can be read with a 16-byte load)
  corner_buffer_.assign(9 * nt + 4, 0.0f);
  edge_margin_.resize(nt);
  for (size_t t = 0; t < nt; ++t) GrowTriangle(static_cast<int>(t));
  // a deformable scene: DYNAMIC (two-level: only modified groups are refit), LOW quality, ROBUST
  // (not COMPACT: its indexed leaves refit in 40 % of the time but reported a different hit set on
  // one sample of the ensemble demo, 2026-11-24)
  RTCScene scene = rtcNewScene(Dev(*device_));
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_DYNAMIC | RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
  rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_LOW);
  for (size_t g = 0; g + 1 < group_first_.size(); ++g) {
    RTCGeometry geom = rtcNewGeometry(Dev(*device_), RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetGeometryBuildQuality(geom, RTC_BUILD_QUALITY_REFIT);
    // the group's own run of corners (a refit reads them in one sweep; a single group's run is the
    // whole buffer, in triangle order)
    const int first = group_first_[g], count = group_first_[g + 1] - first;
    rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, corner_buffer_.data(),
                               9 * sizeof(float) * first, 3 * sizeof(float), 3 * count);
    auto* index = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), count));
    for (int i = 0; i < count; ++i) {
      const int slot = Slot(group_triangles_[first + i]) - first;
      for (int k = 0; k < 3; ++k) index[3 * i + k] = static_cast<unsigned>(3 * slot + k);
    }
    rtcCommitGeometry(geom);
    // determinism: geometry ids are the group indices
    rtcAttachGeometryByID(scene, geom, static_cast<unsigned>(g));
    geometries_.push_back(geom);
  }
  scene_ = scene;
  rtcCommitScene(scene);
}

EmbreeLocator::~EmbreeLocator() {
  for (void* g : geometries_) rtcReleaseGeometry(static_cast<RTCGeometry>(g));
  rtcReleaseScene(static_cast<RTCScene>(scene_));
}

void EmbreeLocator::InflateVertex(const std::vector<Vec3>& vertices, int v) {
  // the float surface sits `inflation_` outside the double one (along the vertex normal), so a
  // segment through a silhouette edge in double still meets the float triangle. Vertices at one
  // rest position (a display mesh's seams) share the normal of all their triangles, summed from the
  // lowest index: they move alike and the float surface keeps no crack the double one does not have
  Vec3 normal = Vec3::Zero();
  const int first = LowestTwin(v);
  int u = first;
  do {
    for (int k = ring_.offsets[u]; k < ring_.offsets[u + 1]; ++k) {
      const auto& t = triangles_[ring_.ids[k]];
      normal += TriangleCross(vertices[t[0]], vertices[t[1]], vertices[t[2]]);
    }
    u = twin_next_[u];
  } while (u != first);
  const double len = normal.norm();
  inflated_[v] = (len > 0.0 ? Vec3(vertices[v] + (inflation_ / len) * normal) : vertices[v]).cast<float>();
}

void EmbreeLocator::GrowTriangle(int t) {
  // where two faces fold back onto each other (crushed sheet metal) their vertex normals cancel and
  // the inflation may pull the fold's edge in: a segment through the fold, a hair from its edge,
  // crossed both faces in double and neither in float. So each float triangle is its inflated one
  // grown about its centre until every edge stands kGrowth inflations further out; neighbours
  // overlap, which only adds candidates
  const auto& tri = triangles_[t];
  const Vec3 a = inflated_[tri[0]].cast<double>(), b = inflated_[tri[1]].cast<double>(),
             c = inflated_[tri[2]].cast<double>();
  const Vec3 centre = (a + b + c) / 3.0;
  // an edge's distance from the centre is a third of its altitude
  const double twice_area = TriangleCross(a, b, c).norm();
  const double longest = std::sqrt(std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()}));
  const double farthest = std::sqrt(
      std::max({(a - centre).squaredNorm(), (b - centre).squaredNorm(), (c - centre).squaredNorm()}));
  double scale = 1.0;
  if (twice_area > 0.0) {
    scale += std::min(3.0 * kGrowth * inflation_ * longest / twice_area, kMaxCornerShift * inflation_ / farthest);
  }
  // a hit's barycentric distance from the grown edges exceeds its distance from the inflated ones by
  // at most (scale - 1) / 3; a sliver thinner than the margin always gets the double test
  const double margin = twice_area > 0.0 ? kInsideMargin * inflation_ * longest / twice_area + (scale - 1.0) / 3.0 : 1.0;
  edge_margin_[t] = static_cast<float>(std::min(margin, 1.0));
  float* out = &corner_buffer_[9 * Slot(t)];
  for (const Vec3& p : {a, b, c}) {
    const Vec3 grown = centre + scale * (p - centre);
    for (int k = 0; k < 3; ++k) *out++ = static_cast<float>(grown[k]);
  }
}

void EmbreeLocator::LinkTwins(const std::vector<Vec3>& vertices) {
  // vertices at exactly one position: a cycle through them in increasing index
  const int nv = static_cast<int>(vertices.size());
  std::vector<int> order(nv);
  for (int v = 0; v < nv; ++v) order[v] = v;
  auto key = [&](int v) { return std::array<double, 3>{vertices[v].x(), vertices[v].y(), vertices[v].z()}; };
  std::sort(order.begin(), order.end(), [&](int a, int b) { return key(a) != key(b) ? key(a) < key(b) : a < b; });
  twin_next_.resize(nv);
  for (int i = 0; i < nv;) {
    int j = i;
    while (j < nv && key(order[j]) == key(order[i])) ++j;
    for (int k = i; k < j; ++k) twin_next_[order[k]] = order[k + 1 < j ? k + 1 : i];
    i = j;
  }
}

int EmbreeLocator::LowestTwin(int v) const {
  // the cycle rises in index and wraps from its highest vertex to its lowest
  int u = v;
  while (twin_next_[u] > u) u = twin_next_[u];
  return twin_next_[u];
}

void EmbreeLocator::Update(const std::vector<Vec3>& vertices, const std::vector<int>& moved) {
  // vertices whose position or normal changed: the moved ones and their neighbours
  std::vector<int> affected;
  for (int v : moved) {
    for (int k = ring_.offsets[v]; k < ring_.offsets[v + 1]; ++k) {
      for (int corner : triangles_[ring_.ids[k]]) {
        // the corner and the vertices at its rest position (they share its normal: marked together)
        if (affected_[corner]) continue;
        int u = corner;
        do {
          affected_[u] = 1;
          affected.push_back(u);
          u = twin_next_[u];
        } while (u != corner);
      }
    }
  }
  // their inflated positions, in parallel (each writes its own vertex)
  ForEachChunk(affected.size(), [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) InflateVertex(vertices, affected[i]);
  });
  // triangles with an inflated corner that moved, each grown again once (at its lowest such corner),
  // in parallel (each writes its own corners), and their groups refit
  std::vector<std::vector<int>> grown(ChunkCount(affected.size()));
  ForEachChunk(affected.size(), [&](std::size_t chunk, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const int v = affected[i];
      for (int k = ring_.offsets[v]; k < ring_.offsets[v + 1]; ++k) {
        const int t = ring_.ids[k];
        const bool lowest = std::none_of(triangles_[t].begin(), triangles_[t].end(),
                                         [&](int c) { return c < v && affected_[c]; });
        if (!lowest) continue;
        GrowTriangle(t);
        grown[chunk].push_back(t);
      }
    }
  });
  std::vector<char> dirty(geometries_.size(), 0);
  for (const std::vector<int>& chunk : grown)
    for (int t : chunk) dirty[triangle_slot_.empty() ? 0 : triangle_slot_[t] / kGroupSize] = 1;
  for (int v : affected) affected_[v] = 0;
  // refit only the groups that hold a changed vertex; the scene commits before its next queries
  for (size_t g = 0; g < geometries_.size(); ++g) {
    if (!dirty[g]) continue;
    auto geom = static_cast<RTCGeometry>(geometries_[g]);
    rtcUpdateGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0);
    rtcCommitGeometry(geom);
    uncommitted_ = true;
  }
}

void EmbreeLocator::Prepare(int /*slave_body*/, int /*step*/, const std::vector<int>& /*keys*/,
                            const std::function<Vec3(int)>& /*position*/) {
  Commit();
}

void EmbreeLocator::Commit() {
  // a body that is never a master (crushed against a rigid barrier) never pays for a commit
  if (!uncommitted_) return;
  rtcCommitScene(static_cast<RTCScene>(scene_));
  uncommitted_ = false;
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
  ctx.ray_length = Vec3(rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z).norm();
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
  NearContext near{out, this};
  rtcPointQuery(static_cast<RTCScene>(scene_), &query, &context, CollectNearPrimitive, &near);
}

size_t EmbreeLocator::HostBytes() const {
  auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  return bytes(geometries_) + bytes(inflated_) + bytes(corner_buffer_) + bytes(triangles_) +
         bytes(ring_.offsets) + bytes(ring_.ids) + bytes(group_first_) + bytes(group_triangles_) +
         bytes(triangle_slot_) + bytes(edge_margin_) + bytes(twin_next_) +
         bytes(affected_);
}

LocatorFactory MakeEmbreeLocatorFactory(std::shared_ptr<const EmbreeDevice> device) {
  return [device](const TriMesh& mesh) { return std::make_unique<EmbreeLocator>(device, mesh); };
}

}  // namespace dymesh::accel
