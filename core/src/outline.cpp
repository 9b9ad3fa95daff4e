#include "dymesh/core/outline.h"

#include <algorithm>

namespace dymesh {
namespace {

// z of (a - o) x (b - o): > 0 when o, a, b turn counter-clockwise
double Turn(const Vec2& o, const Vec2& a, const Vec2& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

}  // namespace

std::vector<Vec2> ConvexHull(std::vector<Vec2> points) {
  // sort and deduplicate (lexicographic on x, then y)
  auto less = [](const Vec2& a, const Vec2& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); };
  std::sort(points.begin(), points.end(), less);
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  // Andrew's monotone chain: lower hull left to right, then upper hull right to left
  std::vector<Vec2> hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && Turn(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && Turn(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);  // the last point repeats the first
  return hull;
}

std::vector<Vec2> PlanOutline(const std::vector<Vec3>& vertices, const RigidState& rigid) {
  // every vertex to the earth frame, dropped on the ground plane
  const Mat3 rotation = rigid.Rotation();
  std::vector<Vec2> points;
  points.reserve(vertices.size());
  for (const Vec3& p : vertices) {
    const Vec3 earth = rigid.position + rotation * p;
    points.emplace_back(earth.x(), earth.y());
  }
  return ConvexHull(std::move(points));
}

}  // namespace dymesh
