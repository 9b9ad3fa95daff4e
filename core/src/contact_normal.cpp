// Which normal of a deformable master's face a deformable slave node is pushed and loaded along
// (contact.contact_normal; spec §2 leaves the push to the search method, §5 asks for equal and opposite
// forces: README, the choices table).
#include "dymesh/core/contact_step.h"
#include "dymesh/core/geometry.h"
#include "contact_pass_frame.h"

namespace dymesh {
namespace {

// a slave face counts as facing the master's face when turned within 60 degrees of it
constexpr double kFacesSquarely = 0.5;
// a rest normal the crush turned over 78 degrees away is not taken (the face is folded over)
constexpr double kLeastRestAgreement = 0.2;

}  // namespace

Vec3 ContactEngine::ConformingNormal(const PassFrame& f, int v, int t, const Vec3& crushed) const {
  // the master face's rest normal, turned with the master (its frame is the master's)
  const auto& face = f.master_model->mesh.triangles[t];
  const auto& at = f.master_model->mesh.vertices;
  const Vec3 rest = TriangleCross(at[face[0]], at[face[1]], at[face[2]]).normalized();
  // an uncrushed face (most of them early in a contact): both normals are the same, nothing to choose
  if (rest == crushed || !(rest.dot(crushed) > kLeastRestAgreement)) return crushed;
  // the node's own rest faces that face the master's rest face, area-weighted (master frame): at the
  // edge of a contact the node's side faces are left out (they face across it)
  const BodyModel& slave = *f.slave_model;
  Vec3 own = Vec3::Zero();
  for (int i = slave.vertex_triangles.offsets[v]; i < slave.vertex_triangles.offsets[v + 1]; ++i) {
    const Vec3 area = f.r_slave_to_master * slave.rest_area[slave.vertex_triangles.ids[i]].cast<double>();
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
