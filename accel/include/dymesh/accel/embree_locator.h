#pragma once
#include <memory>
#include <string>

#include "dymesh/core/locator.h"

/// Embree BVH search: one scene per body in body-fixed coordinates, refit after crush.
namespace dymesh {

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
/// or every triangle near a point (point query). The float surface is inflated by a few ulps so that
/// no segment the double-precision test accepts slips past a silhouette edge.
class EmbreeLocator final : public Locator {
 public:
  EmbreeLocator(std::shared_ptr<const EmbreeDevice> device, const TriMesh& mesh);
  ~EmbreeLocator() override;
  EmbreeLocator(const EmbreeLocator&) = delete;
  EmbreeLocator& operator=(const EmbreeLocator&) = delete;

  void Update(const std::vector<Vec3>& vertices) override;
  void TrianglesAlongSegment(int key, const Vec3& origin, const Vec3& dir, double length,
                             std::vector<Candidate>* out) const override;
  void TrianglesNearPoint(int key, const Vec3& p, double radius, std::vector<Candidate>* out) const override;

  /// The Embree scene (RTCScene), for benchmarks that cast raw rays on the same BVH.
  void* scene() const { return scene_; }

 private:
  void CopyVertices(const std::vector<Vec3>& vertices);

  std::shared_ptr<const EmbreeDevice> device_;
  void* scene_ = nullptr;
  void* geometry_ = nullptr;
  float* vertex_buffer_ = nullptr;  // Embree-owned float3 vertices (with padding)
  double inflation_ = 0.0;          // [m] float surface offset outward along the vertex normals
  size_t vertex_count_ = 0;
  std::vector<std::array<int, 3>> triangles_;
  VertexTriangles ring_;            // triangles around each vertex (candidates beside a hit)
};

/// Factory for the contact engine; all locators share one device.
LocatorFactory MakeEmbreeLocatorFactory(std::shared_ptr<const EmbreeDevice> device);

}  // namespace dymesh
