#include "dymesh/accel/brute_force_locator.h"

#include <cmath>

#include "dymesh/core/geometry.h"

namespace dymesh::accel {

BruteForceLocator::BruteForceLocator(const TriMesh& mesh) : triangles_(mesh.triangles), vertices_(mesh.vertices) {}

void BruteForceLocator::Update(const std::vector<Vec3>& vertices, const std::vector<int>& moved) {
  for (int v : moved) vertices_[v] = vertices[v];
}

void BruteForceLocator::TrianglesAlongSegment(int /*key*/, const Vec3& origin, const Vec3& dir, double length,
                                              std::vector<Candidate>* out) const {
  // every triangle whose plane the segment crosses inside the triangle, in double precision
  const double slack = kSegmentSlack * (1.0 + length);
  for (size_t t = 0; t < triangles_.size(); ++t) {
    double dist = 0.0;
    if (SegmentCrossesTriangle(origin, dir, length, vertices_[triangles_[t][0]], vertices_[triangles_[t][1]],
                               vertices_[triangles_[t][2]], slack, &dist)) {
      out->push_back({static_cast<int>(t), true});
    }
  }
}

void BruteForceLocator::TrianglesNearPoint(int /*key*/, const Vec3& p, double radius, std::vector<Candidate>* out) const {
  // every triangle whose bounding box comes within the radius
  for (size_t t = 0; t < triangles_.size(); ++t) {
    const Vec3& a = vertices_[triangles_[t][0]];
    const Vec3& b = vertices_[triangles_[t][1]];
    const Vec3& c = vertices_[triangles_[t][2]];
    const Vec3 lo = a.cwiseMin(b).cwiseMin(c), hi = a.cwiseMax(b).cwiseMax(c);
    const Vec3 nearest = p.cwiseMax(lo).cwiseMin(hi);
    if ((nearest - p).norm() <= radius) out->push_back({static_cast<int>(t), false});
  }
}

LocatorFactory MakeBruteForceLocatorFactory() {
  return [](const TriMesh& mesh) { return std::make_unique<BruteForceLocator>(mesh); };
}

}  // namespace dymesh::accel
