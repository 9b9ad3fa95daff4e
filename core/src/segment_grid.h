#pragma once
#include <array>
#include <vector>

#include "dymesh/core/mesh.h"

namespace dymesh {

/// A body's triangles binned on a uniform 3-D grid (its own frame), about one triangle per cell:
/// where a segment (an edge of another body) passes through the surface. The initial-overlap check
/// uses it for bodies whose surfaces cross with no vertex of either inside the other (a coarse box
/// threaded on a wall).
class SegmentGrid {
 public:
  explicit SegmentGrid(const TriMesh& mesh);

  /// Fractions s in (0, 1), ascending, where the segment p0 -> p1 passes through a triangle from one
  /// side of its plane to the other (both ends off the plane by more than round-off: an edge lying on
  /// a face, as a box flush against a wall has, crosses nothing).
  std::vector<double> Crossings(const Vec3& p0, const Vec3& p1) const;

 private:
  std::array<int, 3> CellOf(const Vec3& p) const;
  void CandidatesAlong(const Vec3& p0, const Vec3& p1, std::vector<int>* out) const;

  const TriMesh& mesh_;
  Vec3 lo_, hi_;
  double cell_ = 1.0;
  std::array<int, 3> dims_{1, 1, 1};
  std::vector<int> first_;      // cell c's triangles are ids_[first_[c] .. first_[c + 1])
  std::vector<int> ids_;
  double off_plane_ = 0.0;      // [m] round-off of a plane distance at the mesh's size
};

}  // namespace dymesh
