// spec §7 friction of a pair in contact: mu N at each touching node against its slide at the end of
// the step (backward Euler), the null band as the slide under which it fades, never more than mu N.
#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <vector>

#include "dymesh/core/contact_step.h"

namespace dymesh {
namespace {

using Mat12 = Eigen::Matrix<double, 12, 12>;
using Vec12 = Eigen::Matrix<double, 12, 1>;
using Row12 = Eigen::Matrix<double, 1, 12>;

// [m/s] the least slide a point's damper is read over: a null band of 0 (no fading) keeps it finite
constexpr double kLeastSlide = 1e-6;

// how many times the dampers are read: on the trial motion, then on the motion they leave
constexpr int kDamperReadings = 2;

// no friction on either body of the pair
void ClearFriction(PairLoads* p) {
  for (int k = 0; k < 2; ++k) p->friction_force[k] = p->friction_moment[k] = Vec3::Zero();
}

// the row taking the pair's rates (slot 0's velocity and spin, then slot 1's) to the slave point's
// velocity relative to the master's along t; its transpose takes a force t at the point (on the slave,
// the opposite on the master) to the pair's forces and moments about each CG
Row12 SlideRow(const Vec3& t, int slave_slot, const Vec3& arm_slave, const Vec3& arm_master) {
  Row12 g;
  const int s = 6 * slave_slot, m = 6 * (1 - slave_slot);
  g.segment<3>(s) = t.transpose();
  g.segment<3>(s + 3) = arm_slave.cross(t).transpose();
  g.segment<3>(m) = -t.transpose();
  g.segment<3>(m + 3) = -arm_master.cross(t).transpose();
  return g;
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

double ContactEngine::PairPower(const PairLoads& p, const Vec3 (&force)[2], const Vec3 (&moment)[2],
                                const std::array<RigidState, 2>& trial) const {
  double power = 0.0;  // [W]
  for (int k = 0; k < 2; ++k) {
    const Mat3 r = states_[p.body[k]].rigid.Rotation();
    power += force[k].dot(trial[k].velocity) + moment[k].dot(r * trial[k].omega);
  }
  return power;
}

double ContactEngine::PointDamping(double mu, const PairRates& reference, int slave_side, const ContactPoint& q) const {
  const double slide = AlongSurface(RelativeVelocityAt(reference, slave_side, q), q.normal).norm();
  return mu * q.Carried() / std::max({slide, options_.friction_null_band, kLeastSlide});
}

Mat12 ContactEngine::FrictionDampers(const std::vector<PassSums>& sums, const std::vector<double>& weights,
                                     const PairLoads& pair, double mu, const PairRates& reference,
                                     int lead_side) const {
  // each point damps its slide in the two directions across its normal
  Mat12 damping = Mat12::Zero();
  for (std::size_t i = 0; i < sums.size(); ++i) {
    const int ks = sums[i].slave == pair.body[0] ? 0 : 1, slot = ks == lead_side ? 0 : 1;
    for (const ContactPoint& q : sums[i].points) {
      const double c = weights[i] * PointDamping(mu, reference, ks, q);
      if (!(c > 0.0)) continue;
      const Vec3 t1 = q.normal.unitOrthogonal(), t2 = q.normal.cross(t1);
      const Row12 g1 = SlideRow(t1, slot, q.arm_slave, q.arm_master);
      const Row12 g2 = SlideRow(t2, slot, q.arm_slave, q.arm_master);
      damping.noalias() += c * (g1.transpose() * g1 + g2.transpose() * g2);
    }
  }
  return damping;
}

void ContactEngine::AddDamperFriction(const std::vector<PassSums>& sums, const std::vector<double>& weights,
                                      double mu, const PairRates& reference, const PairRates& after,
                                      PairLoads* p) const {
  // determinism: summed per pass in node order, weighted like the normal loads
  for (std::size_t i = 0; i < sums.size(); ++i) {
    const int ks = sums[i].slave == p->body[0] ? 0 : 1;
    Wrench friction;
    for (const ContactPoint& q : sums[i].points) {
      const double c = PointDamping(mu, reference, ks, q), limit = mu * q.Carried();
      if (!(c > 0.0)) continue;
      Vec3 force = -c * AlongSurface(RelativeVelocityAt(after, ks, q), q.normal);
      if (force.norm() > limit) force *= limit / force.norm();
      friction.Add(force, q.arm_slave, q.arm_master);
    }
    friction.AddToPair(weights[i], ks, p->friction_force, p->friction_moment);
  }
}

void ContactEngine::PairFriction(const std::vector<PassSums>& sums, const std::vector<double>& weights, double dt,
                                 PairLoads* p) const {
  // spec §7 SlaveNodeFriction: mu N at each point against its slide at the end of the step, the slide
  // the friction itself leaves (backward Euler: read against the slide the normal loads leave, it
  // overshot a stopped slide and pushed it back the next step, alternating between mu N and about
  // half of it: a box into another's side at 30 mph, mu 0.5, alternated by 4-6 % of the peak force
  // and its peak fell 4.6 / 9.5 % at dt/2, dt/4; now under 1 % and 0.3 %). Each point is a damper of
  // mu N over its slide, read at no less than the null band: sliding, mu N; a slide under the band
  // (the spec's: no spurious force where the surfaces barely slide) takes friction in proportion. The
  // pair's rates at the step's end solve the dampers with the bodies' mobilities, a 12 x 12 system;
  // the dampers dissipate, so friction never reverses a slide; each point's force is at most mu N
  ClearFriction(p);
  const double mu = 0.5 * (models_[p->body[0]]->friction + models_[p->body[1]]->friction);
  if (!(mu > 0.0)) return;
  const PairRates trial = RatesOf(*p, TrialMotion(*p, dt));
  // determinism: the bodies take the slots in an order they set, not their listing
  const int lead = LeadSlave(p->body[0], p->body[1]) == p->body[0] ? 0 : 1;
  auto slot = [lead](int side) { return side == lead ? 0 : 1; };
  // the bodies' mobilities and the rates the normal loads leave
  Mat12 mobility = Mat12::Zero();
  Vec12 rates;
  for (int k = 0; k < 2; ++k) {
    const int body = p->body[k];
    mobility.block<6, 6>(6 * slot(k), 6 * slot(k)) = Mobility(*models_[body], motions_[body], states_[body].rigid);
    rates.segment<3>(6 * slot(k)) = trial.velocity[k];
    rates.segment<3>(6 * slot(k) + 3) = trial.spin[k];
  }
  // the dampers read on the trial motion, then again on the motion they leave (a sliding point's
  // damper then gives mu N at its slide at the step's end to the square of the step's change in it:
  // read once, the sliding box's friction impulse fell 0.5 % short at the 0.5 ms step)
  PairRates reference = trial, after = trial;
  for (int reading = 0; reading < kDamperReadings; ++reading) {
    if (reading > 0) reference = after;
    const Mat12 damping = FrictionDampers(sums, weights, *p, mu, reference, lead);
    // the rates at the step's end: r = r_trial - dt M C r
    const Vec12 end = (Mat12::Identity() + dt * mobility * damping).partialPivLu().solve(rates);
    for (int k = 0; k < 2; ++k) {
      after.velocity[k] = end.segment<3>(6 * slot(k));
      after.spin[k] = end.segment<3>(6 * slot(k) + 3);
    }
  }
  AddDamperFriction(sums, weights, mu, reference, after, p);
}

}  // namespace dymesh
