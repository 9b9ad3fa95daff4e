#include "dymesh/analysis/crush_reach.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "dymesh/core/simulation.h"

namespace dymesh {
namespace {

// the deepest nodes tested: a crush that went beyond reach is the body's deepest (a node pushed on
// by a face tipped past the body that pushed it), and the test stays cheap on a million vertices
constexpr std::size_t kDeepestNodes = 256;

// the corners of every other body's rest bounding box at every state recorded while the bodies were
// in contact (a node is pushed only then), in `body`'s frame
std::vector<Vec3> OtherBodiesCorners(const Simulation& sim, int body, const std::vector<MeshStats>& rest_stats) {
  std::vector<Vec3> points;
  if (sim.first_contact_time() < 0.0) return points;
  const ContactEngine& engine = sim.engine();
  const double slack = 0.5 * sim.scenario().time_step;  // the recorded times' round-off
  for (int other = 0; other < engine.body_count(); ++other) {
    if (other == body) continue;
    const MeshStats& rest = rest_stats[other];
    std::vector<Vec3> corners;
    for (int corner = 0; corner < 8; ++corner)
      corners.emplace_back((corner & 1) ? rest.max.x() : rest.min.x(), (corner & 2) ? rest.max.y() : rest.min.y(),
                           (corner & 4) ? rest.max.z() : rest.min.z());
    for (const Sample& sample : sim.history()) {
      if (sample.time < sim.first_contact_time() - slack || sample.time > sim.last_contact_time() + slack) continue;
      const RigidState& a = sample.bodies[body].rigid;
      const RigidState& b = sample.bodies[other].rigid;
      const Mat3 to_body = a.Rotation().transpose();
      const Mat3 other_to_earth = b.Rotation();
      for (const Vec3& q : corners) points.push_back(to_body * (b.position + other_to_earth * q - a.position));
    }
  }
  return points;
}

// the body's nodes with the largest crush, deepest first (ties by index)
std::vector<int> DeepestNodes(const BodyState& state) {
  std::vector<int> nodes(state.delta.size());
  std::iota(nodes.begin(), nodes.end(), 0);
  const std::size_t n = std::min(kDeepestNodes, nodes.size());
  std::partial_sort(nodes.begin(), nodes.begin() + static_cast<std::ptrdiff_t>(n), nodes.end(), [&](int x, int y) {
    const double cx = state.delta[x].squaredNorm(), cy = state.delta[y].squaredNorm();
    return cx != cy ? cx > cy : x < y;
  });
  nodes.resize(n);
  return nodes;
}

}  // namespace

NodeBeyondReach DeepestNodeBeyondReach(const Simulation& sim, int body, const std::vector<MeshStats>& rest_stats) {
  NodeBeyondReach worst;
  const std::vector<Vec3> reached = OtherBodiesCorners(sim, body, rest_stats);
  if (reached.empty()) return worst;
  const BodyState& state = sim.engine().state(body);
  const std::vector<Vec3>& rest = sim.engine().model(body).mesh.vertices;
  double worst_excess = 0.0;
  for (int v : DeepestNodes(state)) {
    const double crush = state.delta[v].norm();
    if (!(crush > 0.0)) break;
    // how far along its crush, from its rest place, the other bodies came
    const Vec3 along = state.delta[v] / crush;
    double reach = -INFINITY;
    for (const Vec3& p : reached) reach = std::max(reach, (p - rest[v]).dot(along));
    if (crush - reach > worst_excess) {
      worst_excess = crush - reach;
      worst = {v, crush, reach};
    }
  }
  return worst;
}

}  // namespace dymesh
