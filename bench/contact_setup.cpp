#include "contact_setup.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <stdexcept>

#include "dymesh/accel/embree_locator.h"
#include "dymesh/core/physical_ranges.h"
#include "dymesh/io/body_models.h"
#include "dymesh/io/mesh_import.h"

#ifndef DYMESH_DATA_DIR
#define DYMESH_DATA_DIR "data"
#endif

namespace dymesh::bench {
namespace {

// mesh moved so its bounds centre is the origin
TriMesh Centred(TriMesh mesh) {
  const MeshStats stats = ComputeStats(mesh);
  const Vec3 centre = 0.5 * (stats.min + stats.max);
  for (Vec3& p : mesh.vertices) p -= centre;
  return mesh;
}

std::shared_ptr<const BodyModel> Deformable(const std::string& name, TriMesh mesh) {
  // 2-D A = 300 lb/in, B = 100 lb/in^2 over 30 in, in SI
  std::array<Stiffness, kBodySurfaceCount> k{};
  k.fill(StiffnessFrom2D(52538.0, 2068426.0, 0.762));
  return std::make_shared<const BodyModel>(
      MakeBodyModel(name, std::move(mesh), k, 1400.0, Vec3(500, 2500, 2800).asDiagonal(), 0.1, 0.3, false));
}

}  // namespace

TriMesh LoadDataMesh(const std::string& file, int subdivisions) {
  MeshSource source;
  source.file = std::string(DYMESH_DATA_DIR) + "/meshes/" + file;
  source.axes = {"x", "z", "-y"};
  source.subdivisions = subdivisions;
  return Centred(BuildBodyMesh(source, "(bench)", "mesh"));
}

TriMesh LoadUserMesh(const std::string& path, const std::array<std::string, 3>& axes) {
  MeshSource source;
  source.file = path;
  source.axes = axes;
  TriMesh mesh = Centred(BuildBodyMesh(source, "(bench)", "mesh"));
  // both bodies crush: the checks of a scenario's deformable body (a possible size, a volume)
  const MeshStats stats = ComputeStats(mesh);
  const double extent = (stats.max - stats.min).maxCoeff();
  if (extent < kBodySizeRange.hard_lo || extent > kBodySizeRange.hard_hi) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "builds a body %.4g m across at its largest (the file read in metres); expected a physically "
                  "possible body size in %g .. %g m", extent, kBodySizeRange.hard_lo, kBodySizeRange.hard_hi);
    throw InputError(path, "mesh", text);
  }
  RefuseFlatMesh(mesh, path, "mesh");
  return mesh;
}

ContactSetup PlaceInContact(TriMesh master, TriMesh slave, double penetration, double speed) {
  const MeshStats ms = ComputeStats(master), ss = ComputeStats(slave);
  ContactSetup setup;
  setup.master = Deformable("master", std::move(master));
  setup.slave = Deformable("slave", std::move(slave));
  // the slave heads +y (yaw 90 deg): its front x_max reaches y = master y_min + penetration
  setup.slave_pose.yaw = 1.5707963267948966;
  setup.slave_pose.position = Vec3(0.0, ms.min.y() + penetration - ss.max.x(), 0.0);
  setup.slave_pose.velocity = Vec3(0.0, speed, 0.0);
  return setup;
}

RaySet PassRays(const ContactSetup& setup, const ContactOptions& options) {
  const double backoff = options.search_backoff, reach = options.toofar_maximum;
  const Mat3 r_sm = setup.master_pose.Rotation().transpose() * setup.slave_pose.Rotation();
  const Vec3 t_sm = setup.master_pose.Rotation().transpose() * (setup.slave_pose.position - setup.master_pose.position);
  const MeshStats ms = ComputeStats(setup.master->mesh);
  const Vec3 lo = ms.min.array() - (backoff + reach), hi = ms.max.array() + (backoff + reach);
  // pushback along the relative velocity, into the slave (the velocity search direction)
  const Vec3 dir = -(setup.master_pose.Rotation().transpose() * setup.slave_pose.velocity).normalized();
  RaySet rays;
  rays.length = backoff + reach;
  for (const Vec3& v : setup.slave->mesh.vertices) {
    const Vec3 p = r_sm * v + t_sm;
    if ((p.array() < lo.array()).any() || (p.array() > hi.array()).any()) continue;
    rays.origin.push_back(p - backoff * dir);
    rays.dir.push_back(dir);
  }
  return rays;
}

RaySet SampleRays(const RaySet& rays, size_t limit) {
  const size_t stride = std::max<size_t>(1, (rays.size() + limit - 1) / limit);
  RaySet sample;
  sample.length = rays.length;
  for (size_t i = 0; i < rays.size(); i += stride) {
    sample.origin.push_back(rays.origin[i]);
    sample.dir.push_back(rays.dir[i]);
  }
  return sample;
}

namespace {

// bytes held by Embree, counted by the device's memory monitor
bool CountBytes(void* user, ssize_t bytes, bool /*post*/) {
  static_cast<std::atomic<long long>*>(user)->fetch_add(bytes);
  return true;
}

template <class T>
size_t Bytes(const std::vector<T>& v) { return v.capacity() * sizeof(T); }

}  // namespace

BodyMemory MeasureBodyMemory(const BodyModel& model) {
  BodyMemory m;
  // model: rest mesh, CSR adjacency, surfaces, rest area vectors
  m.model = Bytes(model.mesh.vertices) + Bytes(model.mesh.triangles) + Bytes(model.vertex_triangles.offsets) +
            Bytes(model.vertex_triangles.ids) + Bytes(model.surface) + Bytes(model.rest_area);
  // state: every per-vertex and per-triangle array
  const BodyState s = MakeBodyState(model, RigidState{});
  m.state = Bytes(s.vertices) + Bytes(s.delta) + Bytes(s.delta_max) + Bytes(s.unload) + Bytes(s.node_force) +
            Bytes(s.node_area) + Bytes(s.update_step) + Bytes(s.step_start_deflection) + Bytes(s.vertex_normal) +
            Bytes(s.update_mark) + Bytes(s.tri_normal) + Bytes(s.tri_area) + Bytes(s.contact_normal) +
            model.mesh.vertices.size() * sizeof(Vec3);  // the engine's pending crush of a simultaneous pass pair
  // Embree: scene, BVH and buffers allocated through a monitored device, plus the locator's own copies
  std::atomic<long long> embree_bytes{0};
  auto device = std::make_shared<const accel::EmbreeDevice>();
  rtcSetDeviceMemoryMonitorFunction(static_cast<RTCDevice>(device->handle()), CountBytes, &embree_bytes);
  {
    accel::EmbreeLocator locator(device, model.mesh);
    m.embree = static_cast<size_t>(embree_bytes.load()) + locator.HostBytes();
  }
  return m;
}

}  // namespace dymesh::bench
