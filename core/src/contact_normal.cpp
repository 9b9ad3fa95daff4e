// Which normal of a deformable master's face a deformable slave node is pushed and loaded along
// (contact.contact_normal; README, the choices table).
#include "dymesh/core/contact_step.h"
#include "contact_pass_frame.h"

namespace dymesh {
namespace {

// a slave face counts as facing the master's face when turned within 60 degrees of it
constexpr double kFacesSquarely = 0.5;
// a rest normal the crush turned over 78 degrees away is not taken (the face is folded over)
constexpr double kLeastRestAgreement = 0.2;

// the unit outward normal of rest triangle t of `mesh` (cross product of its edges)
Vec3 RestNormal(const TriMesh& mesh, int t) {
  const auto& tri = mesh.triangles[t];
  const Vec3& a = mesh.vertices[tri[0]];
  return (mesh.vertices[tri[1]] - a).cross(mesh.vertices[tri[2]] - a).normalized();
}

}  // namespace

Vec3 ContactEngine::ConformingNormal(const PassFrame& f, int v, int t, const Vec3& crushed) const {
  // the master face's rest normal, turned with the master (its frame is the master's)
  const Vec3 rest = RestNormal(f.master_model->mesh, t);
  if (!(rest.dot(crushed) > kLeastRestAgreement)) return crushed;
  // the node's own rest faces that face the master's rest face, area-weighted (master frame): at the
  // edge of a contact the node's side faces are left out (they face across it)
  const BodyModel& slave = *f.slave_model;
  Vec3 own = Vec3::Zero();
  for (int i = slave.vertex_triangles.offsets[v]; i < slave.vertex_triangles.offsets[v + 1]; ++i) {
    const auto& tri = slave.mesh.triangles[slave.vertex_triangles.ids[i]];
    const Vec3& a = slave.mesh.vertices[tri[0]];
    const Vec3 area = f.r_slave_to_master * (slave.mesh.vertices[tri[1]] - a).cross(slave.mesh.vertices[tri[2]] - a);
    if (area.normalized().dot(rest) < -kFacesSquarely) own += area;
  }
  if (own.squaredNorm() == 0.0) return crushed;
  // the face tipped by the master's own crush where one corner was pushed back and the next was not
  // (the edge of the contact) faces the node's surface less squarely than its rest face; a face
  // crushed into the node's shape (a nose pressed flat on a side) more
  const Vec3 facing = -own.normalized();
  return facing.dot(rest) > facing.dot(crushed) ? rest : crushed;
}

}  // namespace dymesh
