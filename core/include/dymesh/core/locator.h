#pragma once
#include <functional>
#include <memory>
#include <vector>

#include "dymesh/core/mesh.h"

/// The seam between the contact step and its spatial search (Embree, brute force, neighbour box).
namespace dymesh {

/// Finds candidate master triangles for slave nodes, in the master's body frame. Candidates are a
/// superset filter: the contact step re-tests each in double precision, so a locator may return
/// more than needed but must not miss a triangle the exact test accepts.
class Locator {
 public:
  virtual ~Locator() = default;

  /// Takes the master's current body-frame vertices after crush (refit); orchestrating thread only.
  virtual void Update(const std::vector<Vec3>& vertices) = 0;

  /// Appends the triangles the segment origin + t dir, t in [0, length], passes through.
  /// Threading: const and safe from many threads after Update. Determinism: order unspecified.
  virtual void TrianglesAlongSegment(const Vec3& origin, const Vec3& dir, double length,
                                     std::vector<int>* out) const = 0;

  /// Appends the triangles that come within `radius` of point p.
  /// Threading: const and safe from many threads after Update. Determinism: order unspecified.
  virtual void TrianglesNearPoint(const Vec3& p, double radius, std::vector<int>* out) const = 0;
};

/// Makes a locator for a body's mesh (the rest mesh; Update follows crush).
using LocatorFactory = std::function<std::unique_ptr<Locator>(const TriMesh& mesh)>;

}  // namespace dymesh
