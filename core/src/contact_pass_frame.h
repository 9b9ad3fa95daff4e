#pragma once
// The frame of one contact pass and a located slave node: shared by the contact step's files.
#include <array>
#include <vector>

#include "dymesh/core/contact_step.h"

namespace dymesh {

// the master triangle's stiffness at a contact: its corners' average (spec §5 note, SlaveNodeForce)
inline Stiffness CornerAverage(const BodyModel& model, const std::array<int, 3>& triangle) {
  Stiffness k;
  for (int corner : triangle) {
    const Stiffness& c = model.VertexStiffness(corner);
    k.A += c.A / 3.0;
    k.B += c.B / 3.0;
    k.C += c.C / 3.0;
    k.D += c.D / 3.0;
    k.sat_crush += c.sat_crush / 3.0;
  }
  return k;
}

// spec §5: the master face a slave node presses, as one crushable layer: its corners' average law
// (above) and their mean crush |Delta|
struct MasterLayer {
  Stiffness k;
  double deflection = 0.0;  // [m]
};
inline MasterLayer MasterLayerAt(const BodyModel& model, const BodyState& state, const std::array<int, 3>& triangle) {
  MasterLayer layer{CornerAverage(model, triangle)};
  for (int corner : triangle) layer.deflection += state.delta[corner].norm() / 3.0;
  return layer;
}

// slave-to-master transform and body kinematics of one pass (master frame = master body frame)
struct ContactEngine::PassFrame {
  const BodyModel* master_model;
  const BodyModel* slave_model;
  const BodyState* master;
  BodyState* slave;
  const Locator* master_locator;
  Mat3 r_master, r_slave;   // body -> earth
  Mat3 r_slave_to_master;   // slave body -> master body
  Vec3 t_slave_to_master;   // slave CG in the master frame
  std::vector<Vec3>* pending;  // [m] the slave's new Delta of the nodes that moved (n_vertices)
  double mu;                // contact friction coefficient of the pair
  Vec3 pushed;              // unit direction of the normal impulse on the slave so far (master frame), or zero

  Vec3 ToMaster(const Vec3& p_slave) const { return r_slave_to_master * p_slave + t_slave_to_master; }

  // velocity of the slave node relative to the master material point it sits in, master frame
  Vec3 RelativeVelocity(const Vec3& p_slave, const Vec3& p_master) const {
    const Vec3 v_slave = slave->rigid.velocity + r_slave * slave->rigid.omega.cross(p_slave);
    const Vec3 v_master = master->rigid.velocity + r_master * master->rigid.omega.cross(p_master);
    return r_master.transpose() * (v_slave - v_master);
  }
};

// a slave node matched to a master triangle (master frame): the search direction found the
// triangle; the penetration is across it, the pushback and the contact force along `normal`
struct ContactEngine::Located {
  int triangle = -1;
  double ray_depth = 0.0;    // [m] distance to the surface along the search ray (selects the triangle)
  double depth = 0.0;        // [m] penetration along the triangle's normal (> 0 inside the master)
  Vec3 normal{0, 0, 0};      // the triangle's outward normal (or its rest one: ConformingNormal), unit, master frame
  Vec3 rel_velocity{0, 0, 0};  // [m/s] slave node relative to master, master frame

  // spec §2 TOOFAR: the farthest a step restores, the relative motion of a step plus the margin [m]
  double TooFar(double dt, double margin) const { return rel_velocity.norm() * dt + margin; }
};

}  // namespace dymesh
