#pragma once
#include <memory>
#include <vector>

#include "dymesh/core/body.h"
#include "dymesh/core/scenario.h"

/// Where the bodies start relative to each other: the gap or overlap of every pair at t = 0, and
/// bodies placed at first contact along their velocity.
namespace dymesh {

/// Gap of one pair along the direction it closes in (the relative velocity of `a` against `b`, or
/// the line between the CGs when they do not move relative to each other).
struct PairPlacement {
  int a = -1, b = -1;
  Vec3 direction{1, 0, 0};  ///< earth frame, unit: the way `a` moves relative to `b`
  bool meet = false;        ///< a vertex of one meets the other's surface along `direction`
  double gap = 0.0;         ///< [m] distance to first contact along `direction`; negative: overlap depth
};

/// Gap of every pair at the scenario's initial poses, measured vertex to surface along the closing
/// direction both ways (a's vertices against b's surface and b's against a's). A vertex counts as
/// inside the other body when its surface lies both ahead of and behind it, turned away. An edge that
/// passes through the other's surface is probed at the middle of each stretch between two crossings,
/// so surfaces that cross with no vertex inside overlap too.
std::vector<PairPlacement> MeasurePlacements(const Scenario& scenario,
                                             const std::vector<std::shared_ptr<const BodyModel>>& models);

/// Resolves `place_at_contact` (each such body moved along its velocity relative to the named body
/// until the requested gap remains), then measures every pair. An overlap deeper than the contact
/// tolerance is refused (InputError naming both bodies and the depth) unless the scenario allows it,
/// in which case an `initial_overlap` warning is added. Returns the placements at the final poses.
std::vector<PairPlacement> PlaceBodies(Scenario* scenario, const std::vector<std::shared_ptr<const BodyModel>>& models);

}  // namespace dymesh
