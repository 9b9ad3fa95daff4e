// spec §7 friction of a pair in contact: mu N at each touching node against the slide the step would
// leave, the pair's null band, and Coulomb's bound (never more than stops the slide).
#include <array>
#include <vector>

#include "dymesh/core/contact_step.h"

namespace dymesh {
namespace {

// no friction on either body of the pair
void ClearFriction(PairLoads* p) {
  for (int k = 0; k < 2; ++k) p->friction_force[k] = p->friction_moment[k] = Vec3::Zero();
}

}  // namespace

std::array<RigidState, 2> ContactEngine::TrialMotion(const PairLoads& p, double dt) const {
  // the host's own step under the pair's normal loads alone
  std::array<RigidState, 2> trial;
  for (int k = 0; k < 2; ++k) {
    const int body = p.body[k];
    trial[k] = states_[body].rigid;
    IntegrateRigidBody(*models_[body], motions_[body], p.normal_force[k],
                       trial[k].Rotation().transpose() * p.normal_moment[k], dt, &trial[k]);
  }
  return trial;
}

ContactEngine::PairRates ContactEngine::RatesOf(const PairLoads& p, const std::array<RigidState, 2>& trial) const {
  // both bodies' rates in the earth frame of the step's start, where the points are
  PairRates rates;
  for (int k = 0; k < 2; ++k) {
    rates.velocity[k] = trial[k].velocity;
    rates.spin[k] = states_[p.body[k]].rigid.Rotation() * trial[k].omega;
  }
  return rates;
}

Vec3 ContactEngine::RelativeVelocityAt(const PairRates& r, int slave_side, const ContactPoint& q) {
  const int ks = slave_side, km = 1 - slave_side;
  return r.velocity[ks] + r.spin[ks].cross(q.arm_slave) - r.velocity[km] - r.spin[km].cross(q.arm_master);
}

double ContactEngine::AddFriction(const std::vector<PassSums>& sums, const std::vector<double>& weights,
                                  const std::array<RigidState, 2>& trial, double min_slide, PairLoads* p) const {
  // spec §7 SlaveNodeFriction against the slide at the end of the step, not at its start: a slide
  // friction stopped in the last step starts this one at rest, pointing nowhere, while the normal
  // loads drive it again (read at the step's start, friction held the offset pole's slide every
  // other step: mu N, then 6 lbf)
  const double mu = 0.5 * (models_[p->body[0]]->friction + models_[p->body[1]]->friction);
  const PairRates rates = RatesOf(*p, trial);
  double magnitude = 0.0;  // [N]
  for (std::size_t i = 0; i < sums.size(); ++i) {
    const int ks = sums[i].slave == p->body[0] ? 0 : 1;
    Wrench friction;
    double limits = 0.0;
    // determinism: the pass's points in node order; mu times the normal force each carried over the step
    for (const ContactPoint& q : sums[i].points) {
      const Vec3 v_slide = AlongSurface(RelativeVelocityAt(rates, ks, q), q.normal);
      const double slide = v_slide.norm(), limit = mu * q.Carried();
      if (slide <= min_slide || !(limit > 0.0)) continue;
      friction.Add(-(limit / slide) * v_slide, q.arm_slave, q.arm_master);
      limits += limit;
    }
    friction.AddToPair(weights[i], ks, p->friction_force, p->friction_moment);
    magnitude += weights[i] * limits;
  }
  return magnitude;
}

double ContactEngine::PairPower(const PairLoads& p, const Vec3 (&force)[2], const Vec3 (&moment)[2],
                                const std::array<RigidState, 2>& trial) const {
  double power = 0.0;  // [W]
  for (int k = 0; k < 2; ++k) {
    const Mat3 r = states_[p.body[k]].rigid.Rotation();
    power += force[k].dot(trial[k].velocity) + moment[k].dot(r * trial[k].omega);
  }
  return power;
}

void ContactEngine::PairFriction(const std::vector<PassSums>& sums, const std::vector<double>& weights, double dt,
                                 char* held, PairLoads* p) const {
  // spec §7 friction against the slide the step would leave under the normal loads
  const std::array<RigidState, 2> trial = TrialMotion(*p, dt);
  double magnitude = AddFriction(sums, weights, trial, 0.0, p);
  // spec §7 null band: the pair slides if its points' slides, weighted by their friction (-power /
  // sum of mu N), exceed it; then, or while a slide friction brought under it (or stopped) is held
  // there (static friction), every sliding point takes friction. Otherwise only points sliding past
  // the band do. (Read only point by point, the band switched friction off for single steps when a
  // slide hovered at it: the points' slides just under it, their weighted mean just over)
  const double power = PairPower(*p, p->friction_force, p->friction_moment, trial);  // [W]
  const bool slides = magnitude > 0.0 && -power / magnitude > options_.friction_null_band;
  if (!slides && !*held) {
    ClearFriction(p);
    magnitude = AddFriction(sums, weights, trial, options_.friction_null_band, p);
  }
  *held = LimitFriction(dt, magnitude, trial, p) ? 1 : 0;
}

bool ContactEngine::LimitFriction(double dt, double magnitude, const std::array<RigidState, 2>& trial,
                                  PairLoads* p) const {
  // spec §7 friction is Coulomb's: mu N while sliding, but never more than stops the slide within
  // the step (mu N held over a whole step can reverse a slow slide: friction pushing the bodies the
  // other way). The friction wrench's power on the trial motion (the end of the step without it),
  // against the power it adds to it over dt (the bodies' inverse masses as the host moves them),
  // gives the largest scale that brings the motion it opposes to rest and not beyond
  const double power = PairPower(*p, p->friction_force, p->friction_moment, trial);  // [W]
  double gain = 0.0;                              // [W]
  for (int k = 0; k < 2; ++k) {
    const int body = p->body[k];
    gain += dt * LoadPowerGain(*models_[body], motions_[body], states_[body].rigid, p->friction_force[k],
                               p->friction_moment[k]);
  }
  if (power >= 0.0) {
    // friction that would drive the relative motion, not resist it (held slips too slow to point one
    // way): none
    ClearFriction(p);
    return false;
  }
  // sliding on through the step, mu N throughout: held next if the slide it leaves is under the band
  if (gain <= -power) return (-power - gain) / magnitude < options_.friction_null_band;
  const double scale = -power / gain;
  for (int k = 0; k < 2; ++k) {
    p->friction_force[k] *= scale;
    p->friction_moment[k] *= scale;
  }
  return true;
}

}  // namespace dymesh
