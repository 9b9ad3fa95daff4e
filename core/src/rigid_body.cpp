#include "dymesh/core/rigid_body.h"

#include <algorithm>
#include <cmath>

#include "dymesh/core/units.h"

namespace dymesh {

ExternalLoads MotionModelLoads(MotionModel motion, const BodyModel& model, const RigidState& s,
                               double rest_height) {
  ExternalLoads loads;
  if (motion != MotionModel::kGravityGround || model.mass <= 0.0) return loads;
  // weight (earth z down) against a ground support at the rest height: a stiff critically damped
  // spring, so the car neither sinks nor bounces during the pulse
  const double weight = model.mass * units::kStandardGravity;
  const double stiffness = weight / kGroundStaticDeflection;
  const double damping = 2.0 * std::sqrt(stiffness * model.mass);
  const double support = weight + stiffness * (s.position.z() - rest_height) + damping * s.velocity.z();
  loads.force_earth = Vec3(0.0, 0.0, weight - std::max(support, 0.0));
  return loads;
}

void IntegrateRigidBody(const BodyModel& model, MotionModel motion, const Vec3& force_earth,
                        const Vec3& moment_body, double dt, RigidState* s) {
  if (motion == MotionModel::kFixed || model.mass <= 0.0) return;
  // translation: semi-implicit Euler (new velocity, then position)
  Vec3 accel = force_earth / model.mass;
  // rotation: Euler's equations in the body frame, I w' = M - w x I w
  const Vec3& w = s->omega;
  Vec3 w_dot = model.inertia.ldlt().solve(moment_body - w.cross(model.inertia * w));
  if (motion == MotionModel::kPlanar) {
    // planar option: height, roll and pitch held; yaw about the earth vertical only
    accel.z() = 0.0;
    const double izz = model.inertia(2, 2);
    const Vec3 yaw_moment_earth = s->Rotation() * moment_body;
    w_dot = Vec3(0.0, 0.0, yaw_moment_earth.z() / izz);
    s->velocity.z() = 0.0;
  }
  s->velocity += accel * dt;
  s->omega += w_dot * dt;
  s->position += s->velocity * dt;
  // Euler angles from the body rates (spec §8 DCM sequence)
  const Vec3 rates = EulerRates(s->roll, s->pitch, s->omega);
  if (motion == MotionModel::kPlanar) {
    // spec §8 planar option, roll and pitch held: the body turns about the earth vertical only, so
    // its rates are those of the yaw rate alone (a host's or an API caller's state may bring roll and
    // pitch rates; + 0.0 keeps a level body's zero rates +0)
    const Vec3 yaw_axis(-std::sin(s->pitch), std::sin(s->roll) * std::cos(s->pitch), std::cos(s->roll) * std::cos(s->pitch));
    s->omega = yaw_axis * rates.z() + Vec3::Zero();
    s->yaw += rates.z() * dt;
    return;
  }
  s->roll += rates.x() * dt;
  s->pitch += rates.y() * dt;
  s->yaw += rates.z() * dt;
}

Eigen::Matrix<double, 6, 6> Mobility(const BodyModel& model, MotionModel motion, const RigidState& state) {
  // the host's own step over unit time from rest (no gyroscopic term) under each unit load
  Eigen::Matrix<double, 6, 6> m = Eigen::Matrix<double, 6, 6>::Zero();
  const Mat3 r = state.Rotation();
  for (int c = 0; c < 6; ++c) {
    Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
    (c < 3 ? force : moment)[c % 3] = 1.0;
    RigidState still = state;
    still.velocity = Vec3::Zero();
    still.omega = Vec3::Zero();
    IntegrateRigidBody(model, motion, force, r.transpose() * moment, 1.0, &still);
    m.block<3, 1>(0, c) = still.velocity;
    m.block<3, 1>(3, c) = r * still.omega;
  }
  return m;
}

double KineticEnergy(const BodyModel& model, const RigidState& s) {
  return 0.5 * model.mass * s.velocity.squaredNorm() + 0.5 * s.omega.dot(model.inertia * s.omega);
}

}  // namespace dymesh
