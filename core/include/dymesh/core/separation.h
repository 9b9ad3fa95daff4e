#pragma once
#include <vector>

#include "dymesh/core/body.h"
#include "dymesh/core/outline.h"

/// Free-motion separation: whether two bodies that no longer touch turn or move back into each other
/// (the run's stop at separation asks it before it ends the run; spec §1: the collision is over once
/// its forces have separated the bodies).
namespace dymesh {

/// A body that holds its height (planar or fixed motion) seen in plan, and its free motion: moving on
/// at its velocity and turning at its yaw rate, as without contact loads.
struct PlanMotion {
  std::vector<Vec2> outline;  ///< [m] convex hull of its current, crushed vertices, earth-frame offsets from the CG
  Vec2 position, velocity;    ///< [m], [m/s] CG, earth frame
  double yaw_rate = 0.0;      ///< [rad/s] about the vertical
  double radius = 0.0;        ///< [m] farthest outline point from the CG
};

/// The body's plan outline (PlanOutline about its CG) and free motion now.
PlanMotion PlanMotionOf(const BodyState& state);

/// How long [s] two bodies surely stay apart in free motion, or infinity when that is the whole
/// `horizon`. Apart: every corner of either plan outline outside the other outline stays outside
/// it, and a corner inside it now (the bodies interlock where they crushed, and no node there
/// carries load) goes no more than `deepening` [m] deeper. Conservative advancement: a corner closes
/// on the other outline no faster than the relative CG speed plus the two turns (its own about its
/// CG, the other's about a point at most the CGs' distance away), so the motion is safe for its
/// margin over that speed; the outlines are posed again there, until the horizon or a margin is used
/// up (after kMaxPoses poses: the time reached). The outlines are convex: a corner that enters a
/// concave bay of the other's plan shape counts as meeting it; and where the outlines overlap, a node
/// coming back against a face inside the overlap is not foreseen (README, Known limits).
/// Determinism: serial, in outline order.
double SoonestMeeting(const PlanMotion& a, const PlanMotion& b, double horizon, double deepening);

}  // namespace dymesh
