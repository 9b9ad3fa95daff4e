#pragma once
#include <functional>
#include <memory>
#include <vector>

#include "dymesh/core/mesh.h"

/// The seam between the contact step and its spatial search (Embree, brute force, neighbour box).
namespace dymesh {

/// A master triangle proposed for a node. `inside` means the locator has already shown, with margin,
/// that the segment crosses the triangle inside it, so the exact inside test may be skipped.
struct Candidate {
  int triangle = -1;
  bool inside = false;
};

/// Finds candidate master triangles for slave nodes, in the master's body frame. Candidates are a
/// superset filter: the contact step re-tests each in double precision, so a locator may return
/// more than needed but must not miss a triangle the exact test accepts.
class Locator {
 public:
  virtual ~Locator() = default;

  /// Takes the body's current body-frame vertices after crush (refit); `moved` lists the vertices
  /// that changed since the last update, ascending. Orchestrating thread only.
  virtual void Update(const std::vector<Vec3>& vertices, const std::vector<int>& moved) = 0;

  /// Announces the nodes of body `slave_body` (vertex indices `keys`, ascending) that the coming pass
  /// will locate in this body at step `step`; `position(key)` is a node's position in this body's
  /// frame. Locators that keep per-node lists (the neighbour-box search) refresh them here.
  /// Orchestrating thread only. The default does nothing.
  virtual void Prepare(int slave_body, int step, const std::vector<int>& keys,
                       const std::function<Vec3(int)>& position) {
    (void)slave_body, (void)step, (void)keys, (void)position;
  }

  /// Appends the triangles the segment origin + t dir, t in [0, length], passes through; `key` is
  /// the slave vertex the segment belongs to (as announced by Prepare).
  /// Threading: const and safe from many threads after Update. Determinism: order unspecified.
  virtual void TrianglesAlongSegment(int key, const Vec3& origin, const Vec3& dir, double length,
                                     std::vector<Candidate>* out) const = 0;

  /// Appends the triangles that come within `radius` of point p (slave vertex `key`).
  /// Threading: const and safe from many threads after Update. Determinism: order unspecified.
  virtual void TrianglesNearPoint(int key, const Vec3& p, double radius, std::vector<Candidate>* out) const = 0;
};

/// Makes a locator for a body's mesh (the rest mesh; Update follows crush).
using LocatorFactory = std::function<std::unique_ptr<Locator>(const TriMesh& mesh)>;

}  // namespace dymesh
