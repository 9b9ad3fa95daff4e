#pragma once
#include <vector>

#include "dymesh/core/body.h"
#include "dymesh/core/outline.h"
#include "dymesh/core/rigid_body.h"

/// Free-motion separation: whether two bodies that no longer touch turn or move back into each other
/// (the run's stop at separation asks it before it ends the run; spec §1: the collision is over once
/// its forces have separated the bodies).
namespace dymesh {

/// A body seen in plan, and its free motion: moving on at its velocity and turning at its yaw rate, as
/// without contact loads. A body that holds its height (planar, fixed) turns about the vertical only;
/// one that does not (free, gravity: neither weight nor the ground support at its CG turns it) may
/// also roll and pitch, which moves its outline's points away from the outline so posed.
struct PlanMotion {
  std::vector<Vec2> outline;  ///< [m] convex hull of its current, crushed vertices, earth-frame offsets from the CG
  Vec2 position, velocity;    ///< [m], [m/s] CG, earth frame
  double yaw_rate = 0.0;      ///< [rad/s] about the vertical
  double radius = 0.0;        ///< [m] farthest outline point from the CG
  double wobble_speed = 0.0;  ///< [m/s] the fastest its points depart from the outline posed by the yaw rate alone
};

/// The body's plan outline (PlanOutline about its CG) and free motion now, turning about the vertical
/// only (wobble speed 0).
PlanMotion PlanMotionOf(const BodyState& state);

/// [m/s] The fastest a point of a body that does not hold its height departs, over `horizon` [s] of
/// free motion, from where its present yaw rate alone turns it: its farthest vertex from the CG times
/// the most its angular velocity differs from that turn about the vertical (a point at r from the CG
/// moves at w x r; the posed one at w_z x r, so they part at most at |w - w_z| |r|). The rotation is
/// torque-free (weight and the ground support act at the CG), integrated as the host does in steps of
/// `step`; past kMaxWobbleSteps steps, bounded by its kinetic energy instead (|w| <= sqrt(2T / I_min)).
/// 0 for a planar or fixed body.
double WobbleSpeed(const BodyModel& model, MotionModel motion, const BodyState& state, double horizon, double step);

/// Steps of free rotation WobbleSpeed integrates at most (10 s at the default 0.5 ms step).
inline constexpr int kMaxWobbleSteps = 20000;

/// How long [s] two bodies surely stay apart in free motion, or infinity when that is the whole
/// `horizon`. Apart: every corner of either plan outline outside the other outline stays outside
/// it, and a corner inside it now (the bodies interlock where they crushed, and no node there
/// carries load) goes no more than `deepening` [m] deeper. Conservative advancement: a corner closes
/// on the other outline no faster than the relative CG speed plus the two turns (its own about its
/// CG, the other's about a point at most the CGs' distance away), so the motion is safe for its
/// margin over that speed; the outlines are posed again there, until the horizon or a margin is used
/// up (after kMaxPoses poses: the time reached). A body that rolls or pitches takes its wobble speed
/// off every margin per second and adds it to the closing speed. The outlines are convex: a corner
/// that enters a concave bay of the other's plan shape counts as meeting it; and where the outlines
/// overlap, a node coming back against a face inside the overlap is not foreseen (README, Known
/// limits).
/// Determinism: serial, in outline order.
double SoonestMeeting(const PlanMotion& a, const PlanMotion& b, double horizon, double deepening);

}  // namespace dymesh
