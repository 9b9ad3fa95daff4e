#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "dymesh/core/mesh.h"
#include "dymesh/core/node_force.h"
#include "dymesh/core/stiffness.h"

/// Bodies: the immutable model (mesh, stiffness, inertia) and the mutable state (pose, crush).
namespace dymesh {

/// Immutable description of one body (shared read-only between runs).
struct BodyModel {
  std::string name;
  TriMesh mesh;                      ///< rest (undamaged) mesh in the body frame, origin at the CG [m]
  VertexTriangles vertex_triangles;  ///< CSR adjacency of `mesh`
  std::vector<BodySurface> surface;  ///< surface class per vertex (n_vertices)
  std::array<Stiffness, kBodySurfaceCount> stiffness{};  ///< per-area stiffness by surface
  double mass = 0.0;                 ///< [kg]
  Mat3 inertia = Mat3::Identity();   ///< [kg m^2] about the CG, body axes
  double restitution = 0.0;          ///< [-] e of spec §6
  double friction = 0.0;             ///< [-] vehicle-to-vehicle mu of spec §7
  bool rigid = false;                ///< barriers and poles: take no crush
  double median_edge = 0.0;          ///< [m] median edge length of `mesh` (its typical node spacing)
  /// [m^2] each rest triangle's TriangleCross (twice its area along its outward normal), in single
  /// precision: the conforming contact normal's test of which faces round a node face a master face,
  /// and their weights (n_triangles)
  std::vector<Eigen::Vector3f> rest_area;

  /// Stiffness of vertex v (its surface's coefficients).
  const Stiffness& VertexStiffness(int v) const { return stiffness[static_cast<int>(surface[v])]; }
};

/// Builds a model: adjacency, surface classes and rest area vectors from `mesh` (already in the body
/// frame about the CG). The engine reads all three: build models with it.
BodyModel MakeBodyModel(std::string name, TriMesh mesh, const std::array<Stiffness, kBodySurfaceCount>& stiffness,
                        double mass, const Mat3& inertia, double restitution, double friction, bool rigid);

/// Rigid-body pose and velocity of a body (spec §8), SAE axes, earth frame z down.
struct RigidState {
  Vec3 position{0, 0, 0};   ///< [m] CG in the earth frame
  double roll = 0, pitch = 0, yaw = 0;  ///< [rad] Euler angles (phi, theta, psi)
  Vec3 velocity{0, 0, 0};   ///< [m/s] CG velocity, earth frame
  Vec3 omega{0, 0, 0};      ///< [rad/s] angular velocity (p, q, r), body frame

  /// Direction-cosine matrix, body -> earth.
  Mat3 Rotation() const { return BodyToEarth(roll, pitch, yaw); }
};

/// Mutable state of one body: pose plus structure-of-arrays vertex and triangle state.
struct BodyState {
  RigidState rigid;
  std::vector<Vec3> vertices;        ///< [m] current (damaged) body-frame position (n_vertices)
  std::vector<Vec3> delta;           ///< [m] deformation vector Delta, body frame (n_vertices)
  std::vector<double> delta_max;     ///< [m] DeltaMaxTotal, largest deflection reached (n_vertices)
  std::vector<UnloadState> unload;   ///< unloading state (n_vertices)
  std::vector<double> node_force;    ///< [N] last node force magnitude (n_vertices)
  std::vector<double> node_area;     ///< [m^2] last tributary area projected on the pushback direction (n_vertices)
  std::vector<int> update_step;      ///< step of the node's last update, -1 before any (n_vertices)
  std::vector<Vec3> contact_normal;  ///< [-] master's outward normal at the node's last contact, body frame; zero when free (n_vertices)
  std::vector<double> step_start_deflection;  ///< [m] |Delta| when the current step began (n_vertices)
  std::vector<Vec3> vertex_normal;   ///< [-] AreaWeightedNormal of each vertex, kept by UpdateTriangles (n_vertices)
  std::vector<std::uint8_t> update_mark;  ///< UpdateTriangles' scratch marks, all 0 between calls (n_vertices)
  std::vector<Vec3> tri_normal;      ///< [-] unit outward normal, body frame (n_triangles)
  std::vector<double> tri_area;      ///< [m^2] current area (n_triangles)
  std::vector<int> touching;         ///< vertices in contact at their last update, ascending
  double law_energy = 0.0;           ///< [J] work of the node law on this body's nodes (integral g A d delta)
  double crush_energy = 0.0;         ///< [J] ledger: this body's share of the normal contact work
  double friction_energy = 0.0;      ///< [J] ledger: this body's share of the friction work
};

/// Fresh state at rest pose: undamaged vertices, triangle normals and areas, vertex normals.
BodyState MakeBodyState(const BodyModel& model, const RigidState& rigid);

/// Recomputes normal and area of every triangle touching `vertices` (body frame), and the normal of
/// every corner of those triangles (the one vertex normal a Location reads per node, kept instead of
/// summed again from the faces around each node searched: a quarter of a car-to-car step at 1M
/// triangles). Each vertex listed once (std::invalid_argument otherwise). Threading: in parallel
/// chunks, every triangle and normal computed by one chunk alone, so results do not depend on threads.
void UpdateTriangles(const BodyModel& model, const std::vector<int>& vertices, BodyState* state);

/// Outward normal of vertex v, body frame, unit: the area-weighted mean of the surrounding triangle
/// normals (which way the node's surface faces: facing tests, surface class).
Vec3 AreaWeightedNormal(const BodyModel& model, const BodyState& state, int v);

/// Search direction of USE_LOCAL_AVERAGE_NORMAL at vertex v, body frame, unit: each surrounding
/// triangle's normal weighted by its rest angle at v, times the share of its rest area it keeps, so a
/// node on an edge looks halfway between its faces however they are meshed.
Vec3 LocalAverageNormal(const BodyModel& model, const BodyState& state, int v);

/// Contact area A_v of spec §3 for slave vertex v pressed against a master whose outward normal at
/// the contact is `normal` (body frame), v lying `depth` inside it: v's share (a third of a face wholly
/// in contact) of each surrounding face turned toward the master, projected on the contact plane, and
/// only over the part of the face whose rest shape overlaps the master's tangent plane there. A face
/// reaching far out of the contact (a long side panel behind a crushed corner) counts only where it
/// meets the master, so the area converges as the mesh is refined.
double ContactNodeArea(const BodyModel& model, const BodyState& state, int v, const Vec3& normal, double depth);

}  // namespace dymesh
