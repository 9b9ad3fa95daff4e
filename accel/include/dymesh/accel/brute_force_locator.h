#pragma once
#include "dymesh/core/locator.h"

/// The correctness oracle: every master triangle tested in double precision, O(N * M).
namespace dymesh::accel {

/// Tests every triangle exactly (segment-plane crossing plus the cross-product inside test).
class BruteForceLocator final : public Locator {
 public:
  explicit BruteForceLocator(const TriMesh& mesh);
  void Update(const std::vector<Vec3>& vertices, const std::vector<int>& moved) override;
  void TrianglesAlongSegment(int key, const Vec3& origin, const Vec3& dir, double length,
                             std::vector<Candidate>* out) const override;
  void TrianglesNearPoint(int key, const Vec3& p, double radius, std::vector<Candidate>* out) const override;

 private:
  std::vector<std::array<int, 3>> triangles_;
  std::vector<Vec3> vertices_;  // [m] current body-frame vertices
};

/// Factory for the contact engine.
LocatorFactory MakeBruteForceLocatorFactory();

}  // namespace dymesh::accel
