#include "dymesh/core/separation.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Eigenvalues>

namespace dymesh {
namespace {

// most poses tried before the test gives up and says the bodies may meet
constexpr int kMaxPoses = 200;

// a plan vector turned by an angle about the origin
Vec2 Turned(const Vec2& d, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * d.x() - s * d.y(), s * d.x() + c * d.y()};
}

// the outline's earth-frame points after t seconds of free motion
std::vector<Vec2> PosedOutline(const PlanMotion& b, double t) {
  const Vec2 centre = b.position + b.velocity * t;
  std::vector<Vec2> out;
  out.reserve(b.outline.size());
  for (const Vec2& q : b.outline) out.push_back(centre + Turned(q, b.yaw_rate * t));
  return out;
}

// [m] signed distance of point p from a convex counter-clockwise outline: the largest distance out
// past one of its edges (negative inside: minus the depth; outside, at most the true distance)
double OutsideBy(const Vec2& p, const std::vector<Vec2>& outline) {
  double out = -INFINITY;
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const Vec2& e0 = outline[i];
    const Vec2 edge = outline[(i + 1) % outline.size()] - e0;
    const Vec2 normal(edge.y(), -edge.x());  // outward for counter-clockwise
    out = std::max(out, (p - e0).dot(normal) / normal.norm());
  }
  return out;
}

// [m] every outline corner's distance out of the other outline after t seconds of free motion: a's
// corners against b, then b's against a
std::vector<double> Clearances(const PlanMotion& a, const PlanMotion& b, double t) {
  const std::vector<Vec2> outline_a = PosedOutline(a, t), outline_b = PosedOutline(b, t);
  std::vector<double> out;
  out.reserve(outline_a.size() + outline_b.size());
  for (const Vec2& p : outline_a) out.push_back(OutsideBy(p, outline_b));
  for (const Vec2& p : outline_b) out.push_back(OutsideBy(p, outline_a));
  return out;
}

}  // namespace

PlanMotion PlanMotionOf(const BodyState& state) {
  // the outline about the CG: the body posed at the origin
  RigidState at_cg = state.rigid;
  at_cg.position = Vec3::Zero();
  PlanMotion b{PlanOutline(state.vertices, at_cg), state.rigid.position.head<2>(), state.rigid.velocity.head<2>(),
               (state.rigid.Rotation() * state.rigid.omega).z()};
  for (const Vec2& q : b.outline) b.radius = std::max(b.radius, q.norm());
  return b;
}

double WobbleSpeed(const BodyModel& model, MotionModel motion, const BodyState& state, double horizon, double step) {
  if (HoldsHeight(motion) || model.mass <= 0.0) return 0.0;
  const double reach = FarthestFromOrigin(state.vertices);  // [m] farthest vertex from the CG
  // how far the angular velocity (earth frame) is from the present turn about the vertical
  RigidState free = state.rigid;
  const Vec3 turn(0.0, 0.0, (free.Rotation() * free.omega).z());
  const auto departure = [&](const RigidState& s) { return (s.Rotation() * s.omega - turn).norm(); };
  const double steps = std::ceil(horizon / step);
  if (!(steps <= kMaxWobbleSteps)) {
    // torque-free rotation keeps its energy T = w.Iw/2 >= I_min |w|^2 / 2
    const double smallest = Eigen::SelfAdjointEigenSolver<Mat3>(model.inertia).eigenvalues().minCoeff();
    return reach * (std::sqrt(free.omega.dot(model.inertia * free.omega) / smallest) + turn.norm());
  }
  // the host's own free rotation (spec §8, Euler's equations without a moment), step by step
  double most = departure(free);
  for (int i = 0; i < static_cast<int>(steps); ++i) {
    IntegrateRigidBody(model, MotionModel::kFree6Dof, Vec3::Zero(), Vec3::Zero(), step, &free);
    most = std::max(most, departure(free));
  }
  return reach * most;
}

double SoonestMeeting(const PlanMotion& pa, const PlanMotion& pb, double horizon, double deepening) {
  if (pa.outline.size() < 3 || pb.outline.size() < 3) return INFINITY;  // no outline in plan (a vertical sheet)
  // each corner's clearance to hold: out of the other outline; a corner inside it now (the bodies
  // interlock where they crushed, and no node there carries load) may not go `deepening` deeper
  std::vector<double> floor = Clearances(pa, pb, 0.0);
  for (double& f : floor) f = f > 0.0 ? 0.0 : f - deepening;
  // the fastest a corner of each body can move against the other's outline, in the other's frame:
  // the relative CG speed, its own turn, and the other's turn about a point at most `reach` away
  const double speed = (pb.velocity - pa.velocity).norm();
  const double reach = (pb.position - pa.position).norm() + speed * horizon;
  // and a body that rolls or pitches parts from its posed outline at its wobble speed
  const double wobble = pa.wobble_speed + pb.wobble_speed;
  const double rate_a = speed + std::abs(pa.yaw_rate) * pa.radius + std::abs(pb.yaw_rate) * (reach + pa.radius) + wobble;
  const double rate_b = speed + std::abs(pb.yaw_rate) * pb.radius + std::abs(pa.yaw_rate) * (reach + pb.radius) + wobble;
  if (rate_a <= 0.0 && rate_b <= 0.0) return INFINITY;
  // conservative advancement: each corner's margin over its floor is safe for margin / rate; pose the
  // outlines after the shortest such time and go on, until the horizon or a margin is used up
  double t = 0.0;
  for (int pose = 0; pose < kMaxPoses; ++pose) {
    const std::vector<double> clearance = Clearances(pa, pb, t);
    double safe = INFINITY;
    for (std::size_t i = 0; i < clearance.size(); ++i) {
      const double margin = clearance[i] - floor[i] - wobble * t, rate = i < pa.outline.size() ? rate_a : rate_b;
      if (margin <= 0.0) return t;
      if (rate > 0.0) safe = std::min(safe, margin / rate);
    }
    t += safe;
    if (t >= horizon) return INFINITY;
  }
  return t;
}

}  // namespace dymesh
