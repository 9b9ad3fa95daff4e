#include "dymesh/analysis/plan_overlap.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "dymesh/core/mesh.h"
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

// index of a convex polygon's lowest corner (least y, then least x): where its edges' angles start
std::size_t Lowest(const std::vector<Vec2>& p) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < p.size(); ++i)
    if (p[i].y() < p[best].y() || (p[i].y() == p[best].y() && p[i].x() < p[best].x())) best = i;
  return best;
}

// Minkowski sum of two counter-clockwise convex polygons: their edges merged by angle from each one's
// lowest corner (linear in their corners; a collinear pair of edges is left as two)
std::vector<Vec2> MinkowskiSum(const std::vector<Vec2>& p, const std::vector<Vec2>& q) {
  const std::size_t np = p.size(), nq = q.size(), p0 = Lowest(p), q0 = Lowest(q);
  std::vector<Vec2> sum;
  sum.reserve(np + nq);
  std::size_t i = 0, j = 0;
  while (i < np || j < nq) {
    sum.push_back(p[(p0 + i) % np] + q[(q0 + j) % nq]);
    const Vec2 ep = p[(p0 + i + 1) % np] - p[(p0 + i) % np], eq = q[(q0 + j + 1) % nq] - q[(q0 + j) % nq];
    const double turn = ep.x() * eq.y() - ep.y() * eq.x();  // > 0: p's edge comes first
    if (j == nq || (i < np && turn > 0.0)) ++i;
    else if (i == np || turn < 0.0) ++j;
    else ++i, ++j;
  }
  return sum;
}

// how far `a` must move along unit `n` to leave `b`: both convex, so the set of moves t that keep them
// touching, b - a (the Minkowski sum of b and -a), holds the origin while they overlap, and the move
// leaves it where the ray from the origin along n crosses its boundary (0 when they are apart)
double DepthAlong(const std::vector<Vec2>& a, const std::vector<Vec2>& b, const Vec2& n) {
  std::vector<Vec2> minus_a;
  for (const Vec2& p : a) minus_a.push_back(-p);  // a point reflection keeps the corners counter-clockwise
  const std::vector<Vec2> touching = MinkowskiSum(b, minus_a);
  double exit = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < touching.size(); ++i) {
    const Vec2 e = touching[(i + 1) % touching.size()] - touching[i];
    const Vec2 outward(e.y(), -e.x());  // counter-clockwise: the outward side
    const double ahead = outward.dot(touching[i]);  // > 0 for every edge while the origin is inside
    if (ahead <= 0.0) return 0.0;
    if (outward.dot(n) > 0.0) exit = std::min(exit, ahead / outward.dot(n));
  }
  return std::isfinite(exit) ? exit : 0.0;
}

// overlap of two convex outlines across the edge normals of `edges`: the least (<= 0: apart)
double LeastOverlapAcross(const std::vector<Vec2>& edges, const std::vector<Vec2>& p, const std::vector<Vec2>& q) {
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const Vec2 e = edges[(i + 1) % edges.size()] - edges[i];
    const Vec2 n = Vec2(e.y(), -e.x()).normalized();
    double p_lo = INFINITY, p_hi = -INFINITY, q_lo = INFINITY, q_hi = -INFINITY;
    for (const Vec2& v : p) p_lo = std::min(p_lo, v.dot(n)), p_hi = std::max(p_hi, v.dot(n));
    for (const Vec2& v : q) q_lo = std::min(q_lo, v.dot(n)), q_hi = std::max(q_hi, v.dot(n));
    least = std::min(least, std::min(p_hi - q_lo, q_hi - p_lo));
  }
  return least;
}

// earth z range of a body's rest bounds box posed at `rigid`
std::pair<double, double> HeightRange(const PointBounds& rest, const RigidState& rigid) {
  const Mat3 r = rigid.Rotation();
  double lo = INFINITY, hi = -INFINITY;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p(corner & 1 ? rest.hi.x() : rest.lo.x(), corner & 2 ? rest.hi.y() : rest.lo.y(),
                 corner & 4 ? rest.hi.z() : rest.lo.z());
    const double z = (rigid.position + r * p).z();
    lo = std::min(lo, z), hi = std::max(hi, z);
  }
  return {lo, hi};
}

}  // namespace

double DeepestPlanInterpenetration(const Simulation& sim, int a, int b, double least_height) {
  const BodyModel &ma = sim.engine().model(a), &mb = sim.engine().model(b);
  const std::vector<Vec3> va = OutlineVertices(ma), vb = OutlineVertices(mb);
  const PointBounds sa = BoundsOf(ma.mesh.vertices), sb = BoundsOf(mb.mesh.vertices);
  double deepest = 0.0;
  for (const Sample* state : EvenlySpacedStates(sim, 0)) {
    const RigidState &ra = state->bodies[a].rigid, &rb = state->bodies[b].rigid;
    const auto [a_lo, a_hi] = HeightRange(sa, ra);
    const auto [b_lo, b_hi] = HeightRange(sb, rb);
    if (std::min(a_hi - b_lo, b_hi - a_lo) < least_height) continue;
    const std::vector<Vec2> pa = PlanOutline(va, ra), pb = PlanOutline(vb, rb);
    if (pa.size() < 3 || pb.size() < 3) continue;
    deepest = std::max(deepest, std::min(LeastOverlapAcross(pa, pa, pb), LeastOverlapAcross(pb, pa, pb)));
  }
  return deepest;
}

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
