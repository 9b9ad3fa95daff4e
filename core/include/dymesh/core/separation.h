#pragma once
#include "dymesh/core/body.h"

/// Free-motion separation: whether two bodies that no longer touch turn or move back into each other
/// (the run's stop at separation asks it before it ends the run).
namespace dymesh {

/// Two bodies that hold their height (planar or fixed motion), seen in plan: how long [s] they
/// surely stay apart in free motion (each moving on at its velocity and turning at its yaw rate, as
/// without contact loads), or infinity when that is the whole `horizon`. Apart: every corner of either
/// plan outline (the convex hull of its current, crushed vertices) outside the other outline stays
/// outside it, and a corner inside it now (the bodies interlock where they crushed, and no node there
/// carries load) goes no more than `deepening` [m] deeper. Conservative advancement: a corner closes on
/// the other outline no faster than the relative CG speed plus the two turns (its own about its CG,
/// the other's about a point at most the CGs' distance away), so the motion is safe for its margin over
/// that speed; the outlines are posed again there, until the horizon or a margin is used up (after
/// kMaxPoses poses: the time reached). The outlines are convex: a corner that enters a concave bay of
/// the other's plan shape counts as meeting it; and where the outlines overlap, a node coming back
/// against a face inside the overlap is not foreseen (README, Known limits).
/// Determinism: serial, in vertex order.
double SoonestMeeting(const BodyState& a, const BodyState& b, double horizon, double deepening);

}  // namespace dymesh
