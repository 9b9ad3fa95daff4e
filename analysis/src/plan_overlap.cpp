#include "dymesh/analysis/plan_overlap.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "dymesh/core/outline.h"
#include "dymesh/core/simulation.h"
#include "recorded_states.h"

namespace dymesh {
namespace {

// the rest vertices on the hull of the body-frame x-y projection (a mesh's own plan outline; posing
// them gives the posed outline without going through every vertex at every state)
std::vector<Vec3> OutlineVertices(const BodyModel& model) {
  const std::vector<Vec2> hull = ConvexHull([&] {
    std::vector<Vec2> points;
    for (const Vec3& v : model.mesh.vertices) points.emplace_back(v.x(), v.y());
    return points;
  }());
  auto less = [](const Vec2& p, const Vec2& q) { return p.x() < q.x() || (p.x() == q.x() && p.y() < q.y()); };
  std::vector<Vec2> corners = hull;
  std::sort(corners.begin(), corners.end(), less);
  std::vector<Vec3> on_hull;
  for (const Vec3& v : model.mesh.vertices)
    if (std::binary_search(corners.begin(), corners.end(), Vec2(v.x(), v.y()), less)) on_hull.push_back(v);
  return on_hull;
}

// how far `a` must move along unit `n` to leave `b`: both convex, so the set of moves t that keep them
// touching, b - a (the hull of every corner difference), holds the origin while they overlap, and the
// move leaves it where the ray from the origin along n crosses its boundary (0 when they are apart)
double DepthAlong(const std::vector<Vec2>& a, const std::vector<Vec2>& b, const Vec2& n) {
  std::vector<Vec2> differences;
  differences.reserve(a.size() * b.size());
  for (const Vec2& q : b)
    for (const Vec2& p : a) differences.push_back(q - p);
  const std::vector<Vec2> touching = ConvexHull(std::move(differences));
  double exit = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < touching.size(); ++i) {
    const Vec2 e = touching[(i + 1) % touching.size()] - touching[i];
    const Vec2 outward(e.y(), -e.x());  // counter-clockwise hull: the outward side
    const double ahead = outward.dot(touching[i]);  // > 0 for every edge while the origin is inside
    if (ahead <= 0.0) return 0.0;
    if (outward.dot(n) > 0.0) exit = std::min(exit, ahead / outward.dot(n));
  }
  return std::isfinite(exit) ? exit : 0.0;
}

}  // namespace

double DeepestPlanOverlap(const Simulation& sim, int a, int b, const Vec3& direction) {
  const Vec2 n = Vec2(direction.x(), direction.y());
  if (!(n.norm() > 0.0)) return 0.0;
  const std::vector<Vec3> va = OutlineVertices(sim.engine().model(a)), vb = OutlineVertices(sim.engine().model(b));
  double deepest = 0.0;
  for (const Sample* state : StatesFromFirstContact(sim)) {
    const std::vector<Vec2> pa = PlanOutline(va, state->bodies[a].rigid), pb = PlanOutline(vb, state->bodies[b].rigid);
    if (pa.size() < 3 || pb.size() < 3) continue;
    deepest = std::max(deepest, DepthAlong(pa, pb, n.normalized()));
  }
  return deepest;
}

}  // namespace dymesh
