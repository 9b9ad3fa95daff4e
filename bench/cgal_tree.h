#pragma once
// CGAL's AABB tree as the outside peer of the locate benchmarks: behind the DYMESH_WITH_CGAL option,
// linked by the benchmark program only (never by the dymesh command).
#include <memory>

#include "locate_rates.h"

namespace dymesh::bench {

/// CGAL AABB tree over the master's triangles (double precision), first intersection of each ray.
class CgalTree {
 public:
  explicit CgalTree(const TriMesh& mesh);
  ~CgalTree();
  size_t Locate(const RaySet& rays) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace dymesh::bench
