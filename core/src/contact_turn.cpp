// spec §6 the step in which the approach at a touching node ends: its loading force acts over the part
// of the step before the turn, its rebound force from the peak after it.
#include <array>
#include <vector>

#include "dymesh/core/contact_step.h"

namespace dymesh {
namespace {

// the part of a step in which a point closes: its normal velocity (> 0 separating) at the step's start
// and at its end with every load, linear over the step (closing first, the part before the turn)
double ClosingPart(double at_start, double at_end) {
  if (at_start < 0.0 && at_end <= 0.0) return 1.0;   // closing throughout
  if (at_start >= 0.0 && at_end >= 0.0) return 0.0;  // parting throughout: the approach ended before
  return at_start < 0.0 ? at_start / (at_start - at_end) : at_end / (at_end - at_start);
}

}  // namespace

void ContactEngine::EndApproachWithinStep(std::vector<PassSums>* sums, const std::vector<double>& weights,
                                          const PassSums& rigid_nodes, double dt, PairLoads* p) const {
  if (!options_.turn_within_step) return;  // the loads held over the whole step (before 2026-11-27)
  // the loading parts (force less turn force) of the passes' points, weighted like the pair's normal
  // load, times `sign`, each scaled by the part of the step it acted for or not at all
  auto add_loading = [&](double sign, bool scaled, PairLoads* to) {
    for (std::size_t i = 0; i < sums->size(); ++i) {
      Wrench loading;
      for (const ContactPoint& q : (*sums)[i].points)
        loading.Add((scaled ? q.closing_part : 1.0) * (q.force - q.turn_force) * q.normal, q.arm_slave, q.arm_master);
      loading.AddToPair(sign * weights[i], (*sums)[i].slave == p->body[0] ? 0 : 1, to->normal_force,
                        to->normal_moment);
    }
  };
  // the rigid body's nodes' pushes, which act only while a face's crush grows
  PairLoads rigid;
  rigid.body[0] = p->body[0];
  rigid.body[1] = p->body[1];
  const int rigid_slave = rigid_nodes.slave == p->body[0] ? 0 : 1;
  rigid_nodes.normal.AddToPair(1.0, rigid_slave, rigid.normal_force, rigid.normal_moment);
  // each point's normal velocity at the step's start and at its end on the host's step with every load:
  // the loading part acts while the point closes (held whole over the step, a flat face's constant A
  // turned a parking-lot approach round: a 3000 lb box into a wall at 0.5 mph with e = 0 left at 0.16
  // of its speed, at 0.1 mph at 0.93). Read from the step's end velocities with and without the loading
  // parts instead (the loading impulse capped to stop the approach at the step's end), a point whose
  // rebound alone parted it by the step's end lost its whole step of loading: a box's tail slapping a
  // wall at 45 deg with e 0.3 left turning at 18.9 deg/s, at dt/2 7.9, without the turn 8.1
  const std::array<RigidState, 2> start = {states_[p->body[0]].rigid, states_[p->body[1]].rigid};
  const std::array<RigidState, 2> end = TrialMotion(*p, dt);
  const PairRates rates_start = RatesOf(*p, start), rates_end = RatesOf(*p, end);
  bool turned = false;
  for (PassSums& pass : *sums) {
    const int ks = pass.slave == p->body[0] ? 0 : 1;
    for (ContactPoint& q : pass.points) {
      if (!(q.force > q.turn_force)) continue;
      q.closing_part = ClosingPart(RelativeVelocityAt(rates_start, ks, q).dot(q.normal),
                                  RelativeVelocityAt(rates_end, ks, q).dot(q.normal));
      turned = turned || q.closing_part < 1.0;
    }
  }
  // the rigid nodes' pushes as a whole, by their power on the motion they oppose
  const double rigid_turn = ClosingPart(PairPower(*p, rigid.normal_force, rigid.normal_moment, start),
                                        PairPower(*p, rigid.normal_force, rigid.normal_moment, end));
  if (!turned && rigid_turn >= 1.0) return;
  // the step's normal loads: the loading parts and the rigid nodes' pushes taken out, then put back for
  // the part of the step each acted
  PairLoads turned_loads = *p;
  add_loading(-1.0, false, &turned_loads);
  rigid_nodes.normal.AddToPair(-1.0, rigid_slave, turned_loads.normal_force, turned_loads.normal_moment);
  add_loading(1.0, true, &turned_loads);
  rigid_nodes.normal.AddToPair(rigid_turn, rigid_slave, turned_loads.normal_force, turned_loads.normal_moment);
  *p = turned_loads;
}

}  // namespace dymesh
