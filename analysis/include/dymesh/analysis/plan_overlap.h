#pragma once

#include "dymesh/core/geometry.h"

/// How far two bodies went into each other in plan, against how far they crushed.
namespace dymesh {

class Simulation;

/// [m] How far body `a` went into body `b` in plan along the pair's impulse: over the states from the
/// first contact on (at most 256, evenly spaced, and the last), the largest distance `a`'s rest plan
/// outline would have to move along `direction`'s horizontal part (the impulse `b` gave `a`: back the
/// way it came) to leave `b`'s (0 while apart, or for a vertical impulse). Each outline is the convex
/// hull of the body's rest vertices in the earth x-y plane, posed at the state, taken from the vertices
/// on the hull of its body-frame x-y projection (exact for planar and fixed bodies; one that rolls or
/// pitches a few degrees shifts its outline by that much of its height). Bodies that crush as they
/// meet go in by no more than they crush; bodies that went through each other between their nodes by
/// far more (the whole of one, once through). Along the impulse, not the least way out: two boxes
/// offset so that their corners overlap by 26 in, gone through each other head-on, part sideways by
/// 26 in but along their impulse by their lengths.
double DeepestPlanOverlap(const Simulation& sim, int a, int b, const Vec3& direction);

/// [m] How far bodies `a` and `b` went into each other over the whole run, whether or not they
/// touched: the least translation that parts their rest plan outlines (as above), the largest over the
/// recorded states (at most 256, evenly spaced, and the last) at which their posed bounds overlap in
/// height by `least_height` [m] or more (a car standing on a road body overlaps it in plan only); 0 when
/// they never did. A pair that carried no contact force yet went into each other far passed through
/// unseen (a specified search direction that never looks into the other body).
double DeepestPlanInterpenetration(const Simulation& sim, int a, int b, double least_height);

}  // namespace dymesh
