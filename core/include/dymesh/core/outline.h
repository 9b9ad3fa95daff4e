#pragma once
#include <vector>

#include <Eigen/Core>

#include "dymesh/core/body.h"

/// Plan-view outlines of bodies: the convex hull of a mesh projected on the earth x-y plane (the
/// report's plan views; the stop at separation's forecast).
namespace dymesh {

using Vec2 = Eigen::Vector2d;

/// Convex hull of points, counter-clockwise in (x, y), no collinear points; fewer than three
/// distinct points come back as they are (deduplicated).
std::vector<Vec2> ConvexHull(std::vector<Vec2> points);

/// Outline of body-frame `vertices` at pose `rigid`: the convex hull of their earth x-y projection [m].
std::vector<Vec2> PlanOutline(const std::vector<Vec3>& vertices, const RigidState& rigid);

}  // namespace dymesh
