#pragma once
#include <array>
#include <vector>

#include "dymesh/core/locator.h"
#include "dymesh/core/options.h"

/// The original DyMESH search, kept as the historic baseline: a search box around each slave vertex
/// (GLOBAL_SEARCH_BOX) and per-vertex neighbour-surface lists (NaborSurf) recomputed every
/// CALC_NABOR_INTERVAL steps.
namespace dymesh::accel {

/// Neighbour-box search. Each announced slave vertex keeps the list of master triangles whose
/// bounds meet its search box; a query tests that list exactly. Lists are rebuilt every
/// `calc_nabor_interval` steps, and earlier when the vertex or the master mesh moved so far that the
/// list might no longer cover the search segment (so it never misses what the oracle finds).
class NeighborBoxLocator final : public Locator {
 public:
  /// `options.global_search_box` is the box half-size (0: SetBoxSize, from the mesh extents).
  NeighborBoxLocator(const TriMesh& mesh, const ContactOptions& options);

  void Update(const std::vector<Vec3>& vertices, const std::vector<int>& moved) override;
  void Prepare(int slave_body, int step, const std::vector<int>& keys,
               const std::function<Vec3(int)>& position) override;
  void TrianglesAlongSegment(int key, const Vec3& origin, const Vec3& dir, double length,
                             std::vector<Candidate>* out) const override;
  void TrianglesNearPoint(int key, const Vec3& p, double radius, std::vector<Candidate>* out) const override;

  double box_half_size() const { return half_size_; }
  long long lists_built() const { return lists_built_; }

 private:
  struct NaborList {
    int built_step = -1;         // step of the last rebuild, -1 = never
    Vec3 built_at{0, 0, 0};      // [m] node position at that rebuild, this body's frame
    std::vector<int> surfaces;   // NaborSurf: master triangles meeting the box, ascending
  };
  void BuildGrid();
  void BuildList(const Vec3& p, NaborList* list) const;

  std::vector<std::array<int, 3>> triangles_;
  std::vector<Vec3> vertices_;        // [m] current vertices
  std::vector<Vec3> grid_vertices_;   // [m] vertices when the grid was built (drift reference)
  std::vector<Vec3> tri_min_, tri_max_;  // [m] triangle bounds at the grid build
  double half_size_ = 0.0;            // [m] GLOBAL_SEARCH_BOX half edge
  double slack_ = 0.0;                // [m] movement a list tolerates before it must be rebuilt
  int interval_ = 1;                  // CALC_NABOR_INTERVAL
  double master_drift_ = 0.0;         // [m] largest vertex movement since the grid build
  int grid_step_ = -1;
  // uniform grid of triangle bounds, cell edge = box half-size
  Vec3 grid_origin_{0, 0, 0};
  std::array<int, 3> grid_dims_{1, 1, 1};
  std::vector<std::vector<int>> cells_;
  std::vector<std::vector<NaborList>> lists_;  // per slave body, per slave vertex
  int prepared_body_ = 0;                      // slave body of the coming queries
  long long lists_built_ = 0;
};

/// Factory for the contact engine.
LocatorFactory MakeNeighborBoxLocatorFactory(const ContactOptions& options);

}  // namespace dymesh::accel
