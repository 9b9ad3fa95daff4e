#include "locate_rates.h"

#include <embree3/rtcore.h>

#include <cstring>

#include "dymesh/accel/brute_force_locator.h"

namespace dymesh::bench {
namespace {

// any candidate of the segment passes the exact test
bool AnyExact(const TriMesh& mesh, const std::vector<Vec3>& normals, const std::vector<Candidate>& tris,
              const Vec3& o, const Vec3& d, double length) {
  for (const Candidate& c : tris) {
    // the engine's own exact test
    const auto& tri = mesh.triangles[c.triangle];
    double dist = 0.0;
    if (CandidateCrossing(o, d, 0.0, length, mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]],
                          normals[c.triangle], c.inside, &dist))
      return true;
  }
  return false;
}

}  // namespace

size_t LocateWithEmbreeLocator(const accel::EmbreeLocator& locator, const TriMesh& master,
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

size_t LocateWithRawEmbree(const accel::EmbreeLocator& locator, const RaySet& rays) {
  return RawClosestHits(locator.scene(), rays, 0, rays.size());
}

size_t LocateWithNeighborBox(accel::NeighborBoxLocator* locator, int step, const RaySet& rays, double backoff) {
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
  accel::BruteForceLocator brute(master);
  size_t located = 0;
  std::vector<Candidate> tris;
  for (size_t i = 0; i < rays.size(); ++i) {
    tris.clear();
    brute.TrianglesAlongSegment(static_cast<int>(i), rays.origin[i], rays.dir[i], rays.length, &tris);
    located += !tris.empty();
  }
  return located;
}

}  // namespace dymesh::bench
