#pragma once
#include <functional>

#include "dymesh/core/body.h"

/// The 6-DOF rigid-body host (spec §8): integrates each body's equations of motion over a
/// collision time step with the roll-pitch-yaw DCM, plus the external loads a scenario asks for.
namespace dymesh {

/// How a body may move besides the collision loads.
enum class MotionModel {
  kFree6Dof,      ///< all six degrees of freedom, no gravity
  kPlanar,        ///< height, roll and pitch held: x, y and yaw only (default for vehicles)
  kGravityGround, ///< 6-DOF with gravity and a stiff, critically damped ground support at the initial CG height
  kFixed,         ///< does not move (a barrier bolted to the ground)
};

/// Whether a body of this motion keeps its height (planar or fixed): vertical loads, and moments
/// other than about the vertical, do not move it.
inline bool HoldsHeight(MotionModel motion) { return motion == MotionModel::kPlanar || motion == MotionModel::kFixed; }

/// Static sag [m] of the `gravity` model's ground support under the body's weight: its stiffness is
/// weight / sag and it is critically damped, so its natural frequency sqrt(g / sag) (99 rad/s) is the
/// same whatever the body's mass.
inline constexpr double kGroundStaticDeflection = 0.001;

/// Extra loads a host adds to a body: force in the earth frame, moment in the body frame.
struct ExternalLoads {
  Vec3 force_earth{0, 0, 0};  ///< [N]
  Vec3 moment_body{0, 0, 0};  ///< [N m]
};

/// Loads the motion model adds (gravity and ground support); `rest_height` is the CG height it holds.
ExternalLoads MotionModelLoads(MotionModel motion, const BodyModel& model, const RigidState& state,
                               double rest_height);

/// Advances `state` by dt under `force_earth` and `moment_body` (semi-implicit Euler: velocities
/// first, then positions and Euler angles with the new rates), respecting the motion model.
void IntegrateRigidBody(const BodyModel& model, MotionModel motion, const Vec3& force_earth,
                        const Vec3& moment_body, double dt, RigidState* state);

/// The body's mobility: the velocity and spin (earth frame) the host gives it over unit time from rest
/// under a unit force or moment (earth frame, about the CG); columns force x, y, z, then moment x, y,
/// z. Zero for a fixed or massless body; the planar host's axes only.
Eigen::Matrix<double, 6, 6> Mobility(const BodyModel& model, MotionModel motion, const RigidState& state);

/// Kinetic energy [J], translational plus rotational.
double KineticEnergy(const BodyModel& model, const RigidState& state);

}  // namespace dymesh
