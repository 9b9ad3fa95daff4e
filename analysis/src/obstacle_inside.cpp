#include "dymesh/analysis/obstacle_inside.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "dymesh/core/simulation.h"
#include "recorded_states.h"

namespace dymesh {
namespace {

// a face counts as the body's front (or back) where it is turned within 60 degrees of the line
constexpr double kFacingLine = 0.5;

// open edges a body's mesh may have per triangle and still be judged (NearlyClosed): one per 200
constexpr double kOpenEdgesPerTriangle = 0.005;

// the body's rest (uncrushed) surface seen along a line, per lateral cell: the front-most point of
// faces turned toward the line's outward end and the deepest crush across them there (the corners'
// crush interpolated: a face pushed between its nodes carries its corners' crush), the back-most
// point of faces turned away
struct Cell {
  double front = -INFINITY;
  double crush = 0.0;
  double back = INFINITY;
};

class RestSurfaceAlongLine {
 public:
  RestSurfaceAlongLine(const Vec3& line, double cell) : line_(line), cell_(cell) {
    // two lateral axes, across the line
    const Vec3 seed = std::abs(line.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
    across_[0] = line.cross(seed).normalized();
    across_[1] = line.cross(across_[0]);
  }

  // samples a rest face at spacing under half a cell, so every cell it covers gets a sample
  void AddFace(const Vec3 (&corner)[3], const double (&crush)[3]) {
    const Vec3 normal = TriangleCross(corner[0], corner[1], corner[2]).normalized();
    const double facing = normal.dot(line_);
    if (!(std::abs(facing) > kFacingLine)) return;
    const double longest = std::max({(corner[1] - corner[0]).norm(), (corner[2] - corner[1]).norm(),
                                     (corner[0] - corner[2]).norm()});
    const int steps = std::max(1, static_cast<int>(std::ceil(2.0 * longest / cell_)));
    for (int i = 0; i <= steps; ++i)
      for (int j = 0; i + j <= steps; ++j) {
        const double u = static_cast<double>(i) / steps, v = static_cast<double>(j) / steps;
        const Vec3 p = corner[0] + (corner[1] - corner[0]) * u + (corner[2] - corner[0]) * v;
        Cell& at = cells_[Key(p, 0, 0)];
        const double along = p.dot(line_);
        if (facing < 0.0) {
          at.back = std::min(at.back, along);
          continue;
        }
        at.front = std::max(at.front, along);
        at.crush = std::max(at.crush, (1.0 - u - v) * crush[0] + u * crush[1] + v * crush[2]);
      }
  }

  // how far p lies behind the shallowest rest front round it beyond the deepest crush round it
  // (NaN where a cell round p has no front or back: p is at an edge of the body or outside it, or
  // p lies beyond the body's back)
  double DepthBeyondCrush(const Vec3& p) const {
    double front = INFINITY, crush = 0.0, back = -INFINITY;
    for (int di = -1; di <= 1; ++di)
      for (int dj = -1; dj <= 1; ++dj) {
        const auto it = cells_.find(Key(p, di, dj));
        if (it == cells_.end() || !std::isfinite(it->second.front) || !std::isfinite(it->second.back)) return NAN;
        front = std::min(front, it->second.front);
        crush = std::max(crush, it->second.crush);
        back = std::max(back, it->second.back);
      }
    const double along = p.dot(line_);
    return along > back ? front - along - crush : NAN;
  }

  const Vec3& line() const { return line_; }

 private:
  std::int64_t Key(const Vec3& p, int di, int dj) const {
    const auto i = static_cast<std::int64_t>(std::floor(p.dot(across_[0]) / cell_)) + di;
    const auto j = static_cast<std::int64_t>(std::floor(p.dot(across_[1]) / cell_)) + dj;
    return (i << 32) ^ (j & 0xffffffff);
  }

  Vec3 line_;
  Vec3 across_[2];
  double cell_;
  std::unordered_map<std::int64_t, Cell> cells_;
};

// a closed shell but for a few holes: a front and a back everywhere except at them (the milk truck,
// 8 open edges for 3,624 triangles, a hole in its underside). The display cars' window gaps and
// interior panels leave 1.7-30 % of their edges open or shared by more than two faces
bool NearlyClosed(const MeshStats& rest) {
  return rest.nonmanifold_edges == 0 && rest.open_edges <= kOpenEdgesPerTriangle * rest.triangles;
}

}  // namespace

ObstacleInside DeepestObstacleVertexInside(const Simulation& sim, int body, int obstacle, const Vec3& toward_earth,
                                           const MeshStats& rest) {
  ObstacleInside deepest;
  if (!NearlyClosed(rest) || !(toward_earth.norm() > 0.0)) return deepest;
  const BodyModel& model = sim.engine().model(body);
  const std::vector<const Sample*> states = StatesFromFirstContact(sim);
  if (states.empty()) return deepest;
  // the body's rest surface in its frame, seen along the line the obstacle came in on (the pair's
  // impulse, in the body's frame as the contact began: the body may spin away after it), with the
  // deepest crush each node took by the end (at least what it had at any state: never a flag where
  // the body had crushed round the obstacle)
  const BodyState& s = sim.engine().state(body);
  const Mat3 began_to_body = states.front()->bodies[body].rigid.Rotation().transpose();
  RestSurfaceAlongLine surface((began_to_body * toward_earth).normalized(), MedianEdgeLength(model.mesh));
  for (const auto& tri : model.mesh.triangles) {
    const Vec3 corner[3] = {model.mesh.vertices[tri[0]], model.mesh.vertices[tri[1]], model.mesh.vertices[tri[2]]};
    const double crush[3] = {s.delta_max[tri[0]], s.delta_max[tri[1]], s.delta_max[tri[2]]};
    surface.AddFace(corner, crush);
  }
  // the obstacle's vertices that face into the body along the line, in the body's frame, at the
  // states recorded from the first contact on (one on its flank lies against the crushed surface's
  // walls, across the line)
  const BodyState& o = sim.engine().state(obstacle);
  for (const Sample* sample : states) {
    const RigidState& b = sample->bodies[body].rigid;
    const RigidState& r = sample->bodies[obstacle].rigid;
    const Mat3 earth_to_body = b.Rotation().transpose();
    const Mat3 obstacle_to_body = earth_to_body * r.Rotation();
    const Vec3 offset = earth_to_body * (r.position - b.position);
    for (std::size_t v = 0; v < o.vertices.size(); ++v) {
      if (-(obstacle_to_body * o.vertex_normal[v]).dot(surface.line()) <= kFacingLine) continue;
      const double depth = surface.DepthBeyondCrush(obstacle_to_body * o.vertices[v] + offset);
      if (depth > deepest.depth) deepest = {static_cast<int>(v), depth};
    }
  }
  return deepest;
}

}  // namespace dymesh
