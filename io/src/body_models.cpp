#include "dymesh/io/body_models.h"

#include <cmath>
#include <string>

#include "dymesh/core/run_start.h"
#include "dymesh/io/mesh_import.h"

namespace dymesh {
namespace {

// smallest enclosed volume of a deformable body's mesh, relative to its bounds diagonal cubed (a
// 1 m cube: 0.19; a car shell: ~0.1; a flat sheet: round-off)
constexpr double kMinEnclosedVolume = 1e-6;

// solid box of the mesh bounds: the inertia used when a scenario gives none
Mat3 BoxInertia(double mass, const Vec3& size) {
  const Vec3 sq = size.cwiseProduct(size);
  return Vec3(sq.y() + sq.z(), sq.x() + sq.z(), sq.x() + sq.y()).asDiagonal() * (mass / 12.0);
}

// "1 triangle", "3 triangles"
std::string Count(int n, const std::string& noun) { return std::to_string(n) + " " + noun + (n == 1 ? "" : "s"); }

// a deformable body crushes into a volume: a sheet (one triangle, a flat panel) has none
void RefuseFlatMesh(const TriMesh& mesh, const MeshStats& stats, const std::string& file, const std::string& field) {
  // a body of an impossible size is refused for that, by name (a vertex 100 km off stretched the bounds)
  const double extent = (stats.max - stats.min).maxCoeff();
  if (extent < kBodySizeRange.hard_lo || extent > kBodySizeRange.hard_hi) return;
  const double diagonal = (stats.max - stats.min).norm();
  // about the surface's centroid: a closed mesh's volume, none for a flat sheet however it is turned
  // (about the bounds centre, which a tilted sheet need not pass through, a single tilted triangle
  // enclosed a tetrahedron and was taken)
  const double volume = SignedVolumeAbout(mesh, SurfaceCentroid(mesh));
  if (std::abs(volume) > kMinEnclosedVolume * diagonal * diagonal * diagonal) return;
  throw InputError(file, field,
                   "a deformable body's mesh must enclose a volume; this one (" + Count(stats.triangles, "triangle") +
                       ", " + Count(stats.open_edges, "open edge") +
                       ") encloses none: give a closed or shell mesh, or make the body rigid (\"rigid\": true)");
}

}  // namespace

void RefuseFlatMesh(const TriMesh& mesh, const std::string& file, const std::string& field) {
  RefuseFlatMesh(mesh, ComputeStats(mesh), file, field);
}

std::vector<std::shared_ptr<const BodyModel>> BuildBodyModels(const Scenario& scenario) {
  return BuildBodyModels(scenario, [&](const MeshSource& source, const std::string& field) {
    return BuildBodyMesh(source, scenario.file, field);
  });
}

std::vector<std::shared_ptr<const BodyModel>> BuildBodyModels(const Scenario& scenario, const MeshProvider& mesh_for) {
  std::vector<std::shared_ptr<const BodyModel>> models;
  for (size_t i = 0; i < scenario.bodies.size(); ++i) {
    const BodySpec& b = scenario.bodies[i];
    // mesh in body axes, moved so the CG (given, or the bounds centre) is the origin
    TriMesh mesh = mesh_for(b.mesh, "bodies[" + std::to_string(i) + "].mesh");
    const MeshStats stats = ComputeStats(mesh);
    if (!b.rigid) RefuseFlatMesh(mesh, stats, scenario.file, "bodies[" + std::to_string(i) + "].mesh");
    const Vec3 cg = b.cg.value_or(0.5 * (stats.min + stats.max));
    for (Vec3& p : mesh.vertices) p -= cg;
    const Mat3 inertia = b.inertia_diagonal ? Mat3(b.inertia_diagonal->asDiagonal())
                                            : BoxInertia(b.mass, stats.max - stats.min);
    models.push_back(std::make_shared<const BodyModel>(MakeBodyModel(
        b.name, std::move(mesh), b.stiffness, b.mass, inertia, b.restitution, b.friction, b.rigid)));
  }
  return models;
}

}  // namespace dymesh
