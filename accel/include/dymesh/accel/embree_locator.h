#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "dymesh/core/locator.h"

/// Embree BVH search: one scene per body in body-fixed coordinates, refit after crush.
namespace dymesh::accel {

/// An Embree device shared read-only by every locator of a process (ISA pinned at creation).
class EmbreeDevice {
 public:
  /// `config` is Embree's device configuration; empty pins the ISA this build defaults to.
  explicit EmbreeDevice(const std::string& config = "");
  ~EmbreeDevice();
  EmbreeDevice(const EmbreeDevice&) = delete;
  EmbreeDevice& operator=(const EmbreeDevice&) = delete;
  void* handle() const { return device_; }

 private:
  void* device_ = nullptr;
};

/// Candidate triangles from an Embree scene: every triangle a segment crosses (an intersection
/// filter records each hit and lets traversal go on; hits near an edge add the triangles around it),
/// or every triangle near a point (point query). The float surface is inflated by a few ulps, and each
/// triangle, with its own float corners, grown past its edges by a few more, so that no segment the
/// double-precision test accepts slips past a silhouette edge or through a fold. A large mesh (over
/// 64k triangles) is split into spatially compact groups, one Embree geometry each over the shared
/// corner buffer, so a crush refits only the groups it touched; a smaller one is a single geometry (a
/// scene of three or more geometries costs ~0.4 ms per commit).
class EmbreeLocator final : public Locator {
 public:
  EmbreeLocator(std::shared_ptr<const EmbreeDevice> device, const TriMesh& mesh);
  ~EmbreeLocator() override;
  EmbreeLocator(const EmbreeLocator&) = delete;
  EmbreeLocator& operator=(const EmbreeLocator&) = delete;

  /// Refits the touched groups; the scene itself is committed by Prepare (or Commit).
  void Update(const std::vector<Vec3>& vertices, const std::vector<int>& moved) override;
  /// Commits a pending refit before this body is searched.
  void Prepare(int slave_body, int step, const std::vector<int>& keys,
               const std::function<Vec3(int)>& position) override;
  /// Commits a pending refit (orchestrating thread; before any query after Update).
  void Commit();
  void TrianglesAlongSegment(int key, const Vec3& origin, const Vec3& dir, double length,
                             std::vector<Candidate>* out) const override;
  void TrianglesNearPoint(int key, const Vec3& p, double radius, std::vector<Candidate>* out) const override;

  /// The Embree scene (RTCScene), for benchmarks that cast raw rays on the same BVH.
  void* scene() const { return scene_; }

  /// Mesh triangle of Embree's (geometry, primitive) pair.
  int Triangle(unsigned geom_id, unsigned prim_id) const { return group_triangles_[group_first_[geom_id] + prim_id]; }

  /// Smallest barycentric distance from the edges at which a hit on triangle t is surely inside it.
  float EdgeMargin(int t) const { return edge_margin_[t]; }

  /// Bytes of the locator's own tables (Embree's scene and BVH are counted by the device).
  size_t HostBytes() const;

 private:
  void InflateVertex(const std::vector<Vec3>& vertices, int v);
  void GrowTriangle(int t);
  void LinkTwins(const std::vector<Vec3>& vertices);
  int LowestTwin(int v) const;
  int Slot(int t) const { return triangle_slot_.empty() ? t : triangle_slot_[t]; }

  std::shared_ptr<const EmbreeDevice> device_;
  void* scene_ = nullptr;
  std::vector<void*> geometries_;      // one RTCGeometry per triangle group
  std::vector<Eigen::Vector3f> inflated_;  // vertices moved `inflation_` out along their normals (n_vertices)
  std::vector<float> corner_buffer_;   // float3 corners, three per triangle slot (+ padding)
  double inflation_ = 0.0;             // [m] float surface offset outward along the vertex normals
  std::vector<std::array<int, 3>> triangles_;
  VertexTriangles ring_;               // triangles around each vertex
  std::vector<int> group_first_;       // first slot of each group in group_triangles_ (n_groups + 1)
  std::vector<int> group_triangles_;   // mesh triangles, group by group (n_triangles)
  std::vector<int> triangle_slot_;     // slot of each triangle, group by group (n_triangles; empty: slot = triangle)
  std::vector<float> edge_margin_;     // barycentric margin of a sure inside hit (n_triangles)
  std::vector<int> twin_next_;         // next vertex at the same rest position, a cycle (n_vertices)
  std::vector<std::uint8_t> affected_;  // scratch marks for Update, all 0 between calls (n_vertices)
  bool uncommitted_ = false;           // groups refit since the last scene commit
};

/// Factory for the contact engine; all locators share one device.
LocatorFactory MakeEmbreeLocatorFactory(std::shared_ptr<const EmbreeDevice> device);

}  // namespace dymesh::accel
