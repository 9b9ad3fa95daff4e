#include "dymesh/analysis/summary.h"

#include <algorithm>
#include <cmath>

#include "dymesh/analysis/run_assessment.h"

namespace dymesh {

Vec3 BodyFrameImpulse(const Simulation& sim, int body) {
  Vec3 impulse = Vec3::Zero();
  for (const Sample& s : sim.history()) impulse += s.bodies[body].loads.force_body * s.step;
  return impulse;
}

std::vector<double> VertexCrush(const Simulation& sim, int body) {
  const BodyState& state = sim.engine().state(body);
  std::vector<double> crush(state.delta.size());
  for (std::size_t v = 0; v < crush.size(); ++v) crush[v] = state.delta[v].norm();
  return crush;
}

namespace {

BodySummary SummarizeBody(const Simulation& sim, int i) {
  const BodyModel& model = sim.engine().model(i);
  const BodyState& state = sim.engine().state(i);
  const RigidState& first = sim.history().front().bodies[i].rigid;
  BodySummary b;
  b.name = model.name;
  // delta-V of the CG, in the earth frame and in the body axes at t = 0
  b.delta_v_earth = state.rigid.velocity - first.velocity;
  b.delta_v_body = first.Rotation().transpose() * b.delta_v_earth;
  b.delta_v = b.delta_v_earth.norm();
  // PDOF: direction the collision force comes from, 0 deg frontal, +90 deg from the right (SAE)
  const Vec3 impulse = BodyFrameImpulse(sim, i);
  b.pdof_deg = impulse.head<2>().norm() > 0.0 ? std::atan2(-impulse.y(), -impulse.x()) * kRadToDeg : 0.0;
  const int clock = static_cast<int>(std::lround((b.pdof_deg < 0 ? b.pdof_deg + 360.0 : b.pdof_deg) / 30.0)) % 12;
  b.pdof_clock = clock == 0 ? 12 : clock;
  // pulse: peak resultant acceleration, average over the contact duration
  for (const Sample& s : sim.history()) {
    b.peak_accel = std::max(b.peak_accel, s.bodies[i].accel_body.norm());
    b.peak_contact_area = std::max(b.peak_contact_area, s.bodies[i].contact_area);
  }
  // the crush the other bodies left to this body's nodes, at its loaded steps
  double peak_load = 0.0;
  for (const Sample& s : sim.history()) peak_load = std::max(peak_load, s.bodies[i].loads.force_earth.norm());
  for (const Sample& s : sim.history())
    if (s.bodies[i].loads.force_earth.norm() >= kLoadedFraction * peak_load)
      b.untaken_crush = std::max(b.untaken_crush, s.bodies[i].untaken_share);
  const double duration = sim.last_contact_time() - sim.first_contact_time();
  b.average_accel = duration > 0.0 ? b.delta_v / duration : 0.0;
  // crush: largest permanent and dynamic deformation, and where
  for (size_t v = 0; v < state.delta.size(); ++v) {
    const double crush = state.delta[v].norm();
    if (crush > b.max_crush) {
      b.max_crush = crush;
      b.max_crush_vertex = static_cast<int>(v);
      b.max_crush_location = model.mesh.vertices[v];
    }
    b.max_dynamic_crush = std::max(b.max_dynamic_crush, state.delta_max[v]);
  }
  b.crush_energy = state.crush_energy;
  b.law_energy = state.law_energy;
  b.friction_energy = state.friction_energy;
  b.support_work = sim.support_work(i);
  b.final_velocity = state.rigid.velocity;
  b.final_yaw_rate = state.rigid.omega.z();
  b.crush_profile = MeasureCrushProfile(model, state);
  return b;
}


// the point of the impulse's line of action nearest the CG, from the impulse J and its moment H
// about the CG (H = r x J): r = J x H / |J|^2 [m, earth frame]
Vec3 LineOfAction(const Vec3& impulse, const Vec3& angular_impulse) {
  if (impulse.squaredNorm() == 0.0) return Vec3::Zero();  // no load acted on the motion: at the CG
  return impulse.cross(angular_impulse) / impulse.squaredNorm();
}

// earth velocity in state `now` of the body's material point at earth offset r from its CG in state `at`
Vec3 PointVelocity(const RigidState& now, const RigidState& at, const Vec3& r) {
  const Mat3 rotation = now.Rotation();
  return now.velocity + (rotation * now.omega).cross(rotation * (at.Rotation().transpose() * r));
}

// [rad/s] the yaw rate an angular impulse about the vertical gives a body, over its yaw inertia; none
// for a body that does not move
double YawRateChange(const Simulation& sim, int body, const Vec3& angular_impulse) {
  if (sim.scenario().bodies[body].motion == MotionModel::kFixed) return 0.0;
  return angular_impulse.z() / sim.engine().model(body).inertia(2, 2);
}

// the impulse's part across the unit normal over its part along it (0 without a normal part)
double ImpulseRatio(const Vec3& impulse, const Vec3& normal) {
  const double along = impulse.dot(normal);
  return along > 0.0 ? (impulse - along * normal).norm() / along : 0.0;
}

// a vector's part the pair's motion takes: horizontal when the height is held
Vec3 Acting(const Vec3& v, bool horizontal) { return horizontal ? Vec3(v.x(), v.y(), 0.0) : v; }

// closing speed when the pair's contact began, separation speed at the end, along its normal impulse
// (friction tilts the whole impulse toward the slide: a car scraping along a wall would read as still
// closing); at the CGs and at the impact point
PairSummary SummarizePair(const Simulation& sim, const PairContact& c) {
  PairSummary p;
  p.a = c.a;
  p.b = c.b;
  // neither body moves vertically: the vertical part of the loads does not act on their motion
  const bool planar = HoldsHeight(sim.scenario().bodies[c.a].motion) && HoldsHeight(sim.scenario().bodies[c.b].motion);
  const Vec3 normal = Acting(c.normal_impulse_on_a, planar);
  p.direction = normal.squaredNorm() > 0.0 ? normal.normalized() : Vec3::Zero();
  const Sample& start = sim.history()[c.first_sample];
  const RigidState &a0 = start.bodies[c.a].rigid, &b0 = start.bodies[c.b].rigid;
  const RigidState &a1 = sim.engine().state(c.a).rigid, &b1 = sim.engine().state(c.b).rigid;
  p.closing_speed = -(a0.velocity - b0.velocity).dot(p.direction);
  p.separation_speed = (a1.velocity - b1.velocity).dot(p.direction);
  // the line of action of the loads that acted: in the plane, the yaw moments only
  const Vec3 impulse = Acting(c.impulse_on_a, planar);
  auto moment = [&](const Vec3& h) { return planar ? Vec3(0.0, 0.0, h.z()) : h; };
  const Vec3 r_a = LineOfAction(impulse, moment(c.angular_impulse_on_a));
  const Vec3 r_b = LineOfAction(-impulse, moment(c.angular_impulse_on_b));
  p.point_closing_speed = -(PointVelocity(a0, a0, r_a) - PointVelocity(b0, b0, r_b)).dot(p.direction);
  p.point_separation_speed = (PointVelocity(a1, a0, r_a) - PointVelocity(b1, b0, r_b)).dot(p.direction);
  p.contact_start = start.time;
  // how much of the impulse friction made, and of each body's turn
  p.impulse_ratio = ImpulseRatio(impulse, p.direction);
  p.yaw_rate_change[0] = YawRateChange(sim, c.a, c.angular_impulse_on_a);
  p.yaw_rate_change[1] = YawRateChange(sim, c.b, c.angular_impulse_on_b);
  p.friction_yaw_rate_change[0] = YawRateChange(sim, c.a, c.friction_angular_impulse_on_a);
  p.friction_yaw_rate_change[1] = YawRateChange(sim, c.b, c.friction_angular_impulse_on_b);
  return p;
}

}  // namespace

Summary Summarize(const Simulation& sim) {
  Summary sum;
  const ContactEngine& engine = sim.engine();
  const Sample& first = sim.history().front();
  for (int i = 0; i < engine.body_count(); ++i) {
    sum.bodies.push_back(SummarizeBody(sim, i));
    // momentum and energy of the bodies that move (fixed barriers have no mass here)
    const BodyModel& model = engine.model(i);
    if (sim.scenario().bodies[i].motion == MotionModel::kFixed) continue;
    sum.momentum_before += model.mass * first.bodies[i].rigid.velocity;
    sum.momentum_after += model.mass * engine.state(i).rigid.velocity;
    sum.kinetic_before += KineticEnergy(model, first.bodies[i].rigid);
    sum.kinetic_after += KineticEnergy(model, engine.state(i).rigid);
  }
  for (const BodySummary& b : sum.bodies) {
    sum.crush_energy += b.crush_energy;
    sum.friction_energy += b.friction_energy;
    sum.law_energy += b.law_energy;
    sum.support_work += b.support_work;
  }
  sum.energy_discontinuity = sum.crush_energy - sum.law_energy;
  const double lost = sum.kinetic_before - sum.kinetic_after;
  // relative to the kinetic energy lost, which the contact work takes and the motion models' loads
  // give (a `gravity` body's weight and ground support); with none lost, contact work of either sign
  // is wholly unbalanced (-100 % or +100 %: a host that holds the bodies' velocities while the contact
  // works, 2026-11-28, read 0.0)
  const double work = sum.crush_energy + sum.friction_energy - sum.support_work;
  sum.energy_balance_error = lost != 0.0 ? (lost + sum.support_work - sum.crush_energy - sum.friction_energy) / lost
                             : work > 0.0 ? -1.0 : work < 0.0 ? 1.0 : 0.0;
  // each pair's closing and separation speed along its impulse; the largest impulse is the main one
  double largest = 0.0;
  for (const PairContact& c : sim.pair_contacts()) {
    sum.pairs.push_back(SummarizePair(sim, c));
    if (c.impulse_on_a.norm() > largest) {
      largest = c.impulse_on_a.norm();
      sum.main_pair = static_cast<int>(sum.pairs.size()) - 1;
    }
  }
  if (sum.main_pair >= 0) {
    const PairSummary& p = sum.pairs[sum.main_pair];
    sum.closing_speed = p.closing_speed;
    sum.separation_speed = p.separation_speed;
  }
  sum.contact_start = sim.first_contact_time();
  sum.contact_end = sim.last_contact_time();
  sum.steps = sim.steps();
  sum.end_time = sim.time();
  sum.diagnostics = sim.diagnostics();
  const RunAssessment assessment = AssessRun(sim, sum);
  sum.status = assessment.status;
  sum.warnings = assessment.warnings;
  return sum;
}

}  // namespace dymesh
