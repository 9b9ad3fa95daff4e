#pragma once
// Two meshes placed in contact, and the Location segments of their slave nodes, for benchmarks.
#include <memory>
#include <string>
#include <vector>

#include "dymesh/core/body.h"
#include "dymesh/core/options.h"

namespace dymesh::bench {

/// A mesh from data/meshes (metres, y up, +x front) in body axes about its bounds centre, with
/// `subdivisions` 1-to-4 midpoint subdivisions (four times the triangles each).
TriMesh LoadDataMesh(const std::string& file, int subdivisions);

/// Any mesh file the user brings (assimp), mapped to body axes by `axes` (as a scenario's
/// mesh.axes, e.g. {"x", "z", "-y"} for a y-up mesh), about its bounds centre.
TriMesh LoadUserMesh(const std::string& path, const std::array<std::string, 3>& axes);

/// Master at the origin; the slave turned 90 degrees, its +x end driven into the master's -y side
/// by `penetration` [m], moving toward it at `speed` [m/s]. Deformable bodies with a plausible
/// stiffness.
struct ContactSetup {
  std::shared_ptr<const BodyModel> master, slave;
  RigidState master_pose, slave_pose;
};
ContactSetup PlaceInContact(TriMesh master, TriMesh slave, double penetration, double speed);

/// Location segments of one pass (master body frame): slave nodes inside the master's bounds grown
/// by the search reach, each cast along the pushback direction, backed off as the engine does.
struct RaySet {
  std::vector<Vec3> origin, dir;
  double length = 0.0;  ///< [m] search_backoff + toofar_maximum
  size_t size() const { return origin.size(); }
};
RaySet PassRays(const ContactSetup& setup, const ContactOptions& options);

/// Every k-th segment, at most `limit` of them (for searches too slow to take them all).
RaySet SampleRays(const RaySet& rays, size_t limit);

/// Bytes one deformable body needs: model (mesh, adjacency, surfaces), state and Embree scene.
struct BodyMemory {
  size_t model = 0, state = 0, embree = 0;
  size_t total() const { return model + state + embree; }
};
BodyMemory MeasureBodyMemory(const BodyModel& model);

}  // namespace dymesh::bench
