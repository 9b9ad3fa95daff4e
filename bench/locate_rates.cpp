#include "locate_rates.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>
#include <embree3/rtcore.h>

#include <cstring>

#include "dymesh/accel/brute_force_locator.h"

namespace dymesh::bench {
namespace {

// any candidate of the segment passes the exact test
bool AnyExact(const TriMesh& mesh, const std::vector<Vec3>& normals, const std::vector<Candidate>& tris,
              const Vec3& o, const Vec3& d, double length) {
  for (const Candidate& c : tris) {
    // as the engine: the depth in double always, the inside test unless proven by the locator
    const auto& tri = mesh.triangles[c.triangle];
    const Vec3& a = mesh.vertices[tri[0]];
    double dist = 0.0;
    if (!RayPlaneDistance(o, d, a, normals[c.triangle], &dist) || dist < 0.0 || dist > length) continue;
    if (c.inside || InsideTriangleCrossProduct(o + dist * d, a, mesh.vertices[tri[1]], mesh.vertices[tri[2]],
                                               normals[c.triangle])) {
      return true;
    }
  }
  return false;
}

}  // namespace

size_t LocateWithEmbreeLocator(const EmbreeLocator& locator, const TriMesh& master,
                               const std::vector<Vec3>& normals, const RaySet& rays) {
  size_t located = 0;
  std::vector<Candidate> tris;
  for (size_t i = 0; i < rays.size(); ++i) {
    tris.clear();
    locator.TrianglesAlongSegment(static_cast<int>(i), rays.origin[i], rays.dir[i], rays.length, &tris);
    located += AnyExact(master, normals, tris, rays.origin[i], rays.dir[i], rays.length);
  }
  return located;
}

size_t RawClosestHits(void* scene, const RaySet& rays, size_t begin, size_t end) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  size_t located = 0;
  for (size_t i = begin; i < end; ++i) {
    RTCRayHit rh;
    std::memset(&rh, 0, sizeof(rh));
    for (int k = 0; k < 3; ++k) {
      (&rh.ray.org_x)[k] = static_cast<float>(rays.origin[i][k]);
      (&rh.ray.dir_x)[k] = static_cast<float>(rays.dir[i][k]);
    }
    rh.ray.tfar = static_cast<float>(rays.length);
    rh.ray.mask = 0xFFFFFFFFu;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(static_cast<RTCScene>(scene), &context, &rh);
    located += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
  }
  return located;
}

size_t LocateWithRawEmbree(const EmbreeLocator& locator, const RaySet& rays) {
  return RawClosestHits(locator.scene(), rays, 0, rays.size());
}

size_t LocateWithNeighborBox(NeighborBoxLocator* locator, int step, const RaySet& rays, double backoff) {
  // lists prepared for every node (rebuilt on the locator's own schedule), then queried
  std::vector<int> keys(rays.size());
  for (size_t i = 0; i < keys.size(); ++i) keys[i] = static_cast<int>(i);
  locator->Prepare(0, step, keys, [&](int i) { return Vec3(rays.origin[i] + backoff * rays.dir[i]); });
  size_t located = 0;
  std::vector<Candidate> tris;
  for (size_t i = 0; i < rays.size(); ++i) {
    tris.clear();
    locator->TrianglesAlongSegment(static_cast<int>(i), rays.origin[i], rays.dir[i], rays.length, &tris);
    located += !tris.empty();
  }
  return located;
}

size_t LocateWithBruteForce(const TriMesh& master, const RaySet& rays) {
  BruteForceLocator brute(master);
  size_t located = 0;
  std::vector<Candidate> tris;
  for (size_t i = 0; i < rays.size(); ++i) {
    tris.clear();
    brute.TrianglesAlongSegment(static_cast<int>(i), rays.origin[i], rays.dir[i], rays.length, &tris);
    located += !tris.empty();
  }
  return located;
}

// CGAL kernel and tree types
using Kernel = CGAL::Simple_cartesian<double>;
using Triangle = Kernel::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle>::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

struct CgalTree::Impl {
  std::vector<Triangle> triangles;
  Tree tree;
};

CgalTree::CgalTree(const TriMesh& mesh) : impl_(std::make_unique<Impl>()) {
  // the tree is built (and its distance structures accelerated) before any query is timed
  auto point = [&](int v) { return Kernel::Point_3(mesh.vertices[v].x(), mesh.vertices[v].y(), mesh.vertices[v].z()); };
  for (const auto& t : mesh.triangles) impl_->triangles.emplace_back(point(t[0]), point(t[1]), point(t[2]));
  impl_->tree.insert(impl_->triangles.cbegin(), impl_->triangles.cend());
  impl_->tree.build();
}

CgalTree::~CgalTree() = default;

size_t CgalTree::Locate(const RaySet& rays) const {
  size_t located = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    // first intersection of the ray, kept when it lies within the segment
    const Kernel::Point_3 o(rays.origin[i].x(), rays.origin[i].y(), rays.origin[i].z());
    const Kernel::Vector_3 d(rays.dir[i].x(), rays.dir[i].y(), rays.dir[i].z());
    const auto hit = impl_->tree.first_intersection(Kernel::Ray_3(o, d));
    if (!hit) continue;
    if (const Kernel::Point_3* p = boost::get<Kernel::Point_3>(&hit->first)) {
      located += CGAL::to_double((*p - o).squared_length()) <= rays.length * rays.length;
    }
  }
  return located;
}

}  // namespace dymesh::bench
