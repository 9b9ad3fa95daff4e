#include "dymesh/core/placement.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "segment_grid.h"

namespace dymesh {
namespace {

constexpr double kNone = std::numeric_limits<double>::infinity();

// the most times a pair's gap is corrected for an overlap its edges show at the vertices' touch (each
// removes at least the overlap at the deepest stretch's middle; one suffices where it is symmetric)
constexpr int kTouchCorrections = 16;

// one body posed in the earth frame
struct PosedBody {
  const BodyModel* model;
  const RigidState* pose;
  Mat3 rotation;
};

// first surface crossing of a ray: distance and whether the face there is turned towards the ray
// (entering the body) or away (leaving it); distance kNone when there is none
struct Crossing {
  double t = kNone;
  bool entering = false;
};

// a body's triangles binned on a grid across one direction d (its own frame): every ray along d
// meets only the triangles of its cell
class ParallelRayGrid {
 public:
  ParallelRayGrid(const TriMesh& mesh, const Vec3& d) : mesh_(mesh), d_(d) {
    // plane axes across d and the projected bounds
    e1_ = d.unitOrthogonal();
    e2_ = d.cross(e1_);
    lo_ = Eigen::Vector2d::Constant(kNone);
    Eigen::Vector2d hi = -lo_;
    for (const Vec3& p : mesh.vertices) {
      lo_ = lo_.cwiseMin(Across(p));
      hi = hi.cwiseMax(Across(p));
    }
    // about one triangle per cell
    const Eigen::Vector2d size = (hi - lo_).cwiseMax(1e-9);
    cell_ = std::sqrt(size.x() * size.y() / static_cast<double>(std::max<std::size_t>(1, mesh.triangles.size())));
    cell_ = std::max(cell_, 1e-6 * size.maxCoeff());
    nu_ = static_cast<int>(size.x() / cell_) + 1;
    nv_ = static_cast<int>(size.y() / cell_) + 1;
    cells_.resize(static_cast<std::size_t>(nu_) * nv_);
    for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) Insert(t);
  }

  // first surface crossing of the ray from q along +d (forward) or -d, within `length`, at least
  // `skip` away (a point on the surface skips its own face when looking back)
  Crossing First(const Vec3& q, bool forward, double length, double skip) const {
    Crossing first;
    const int cell = CellOf(Across(q));
    if (cell < 0) return first;
    const Vec3 dir = forward ? d_ : Vec3(-d_);
    for (int t : cells_[cell]) {
      const auto& tri = mesh_.triangles[t];
      const Vec3 &a = mesh_.vertices[tri[0]], &b = mesh_.vertices[tri[1]], &c = mesh_.vertices[tri[2]];
      double dist = 0.0;
      if (!SegmentCrossesTriangle(q, dir, length, a, b, c, kSegmentSlack * (1.0 + length), &dist)) continue;
      if (dist < skip) continue;
      if (dist < first.t) first = Crossing{std::max(dist, 0.0), TriangleCross(a, b, c).dot(dir) < 0.0};
    }
    return first;
  }

 private:
  Eigen::Vector2d Across(const Vec3& p) const { return {p.dot(e1_), p.dot(e2_)}; }

  int Index(double x, double lo) const { return static_cast<int>(std::floor((x - lo) / cell_)); }

  int CellOf(const Eigen::Vector2d& x) const {
    const int i = Index(x.x(), lo_.x()), j = Index(x.y(), lo_.y());
    return (i < 0 || j < 0 || i >= nu_ || j >= nv_) ? -1 : j * nu_ + i;
  }

  // a triangle goes into every cell its projected bounds touch (one cell of margin for round-off)
  void Insert(int t) {
    Eigen::Vector2d lo = Eigen::Vector2d::Constant(kNone), hi = -lo;
    for (int k = 0; k < 3; ++k) {
      lo = lo.cwiseMin(Across(mesh_.vertices[mesh_.triangles[t][k]]));
      hi = hi.cwiseMax(Across(mesh_.vertices[mesh_.triangles[t][k]]));
    }
    const int i0 = std::max(0, Index(lo.x(), lo_.x()) - 1), j0 = std::max(0, Index(lo.y(), lo_.y()) - 1);
    const int i1 = std::min(nu_ - 1, Index(hi.x(), lo_.x()) + 1), j1 = std::min(nv_ - 1, Index(hi.y(), lo_.y()) + 1);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) cells_[static_cast<std::size_t>(j) * nu_ + i].push_back(t);
  }

  const TriMesh& mesh_;
  Vec3 d_, e1_, e2_;
  Eigen::Vector2d lo_;
  double cell_ = 1.0;
  int nu_ = 1, nv_ = 1;
  std::vector<std::vector<int>> cells_;
};

// the undirected edges of a mesh, each once
std::vector<std::array<int, 2>> Edges(const TriMesh& mesh) {
  std::vector<std::array<int, 2>> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (const auto& tri : mesh.triangles)
    for (int k = 0; k < 3; ++k) edges.push_back({std::min(tri[k], tri[(k + 1) % 3]), std::max(tri[k], tri[(k + 1) % 3])});
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

// a posed body's search structures for gaps measured toward it along one earth direction (both in
// its own frame, so they hold while the other body moves): its triangles across that direction and,
// built when an edge of the other first needs it, its surface for edges passing through it
struct TargetGrids {
  TargetGrids(const PosedBody& target, const Vec3& d) : rays(target.model->mesh, target.rotation.transpose() * d) {}
  ParallelRayGrid rays;
  std::optional<SegmentGrid> surface;
};

// gap from `mover`'s surface to `target`'s along the earth direction `grids` were cast along: the
// smallest entering distance of its vertices, or minus the deepest inside depth (distance back out) of its vertices and of the
// parts of its edges that pass through the target's surface (where no vertex of either body lies
// inside the other, as a coarse box threaded on a wall: before, "gap 2.25 m" and a run through it)
double DirectedGap(const PosedBody& mover, const PosedBody& target, double length, TargetGrids* grids) {
  const ParallelRayGrid& grid = grids->rays;
  double gap = kNone, depth = 0.0;
  auto probe = [&](const Vec3& q) {
    const Crossing ahead = grid.First(q, true, length, -kNone);
    if (ahead.t == kNone) return;
    if (ahead.entering) {
      gap = std::min(gap, ahead.t);
      return;
    }
    // surface ahead turned away: inside when the surface behind is turned away too (a vertex on
    // the far face, as a box pushed exactly through a wall, looks past that face)
    const Crossing behind = grid.First(q, false, length, kSegmentSlack * (1.0 + length));
    if (behind.t != kNone && !behind.entering) depth = std::max(depth, behind.t);
  };
  // the mover's vertices in the target's frame
  std::vector<Vec3> at;
  at.reserve(mover.model->mesh.vertices.size());
  for (const Vec3& vertex : mover.model->mesh.vertices)
    at.push_back(target.rotation.transpose() * (mover.pose->position + mover.rotation * vertex - target.pose->position));
  for (const Vec3& q : at) probe(q);
  // an edge through the target's surface: the middle of each stretch between two crossings (none
  // while the mover's bounds stay clear of the target's: no grid built for bodies that start apart)
  const PointBounds mover_box = BoundsOf(at), target_box = BoundsOf(target.model->mesh.vertices);
  if ((mover_box.lo.array() > target_box.hi.array()).any() || (mover_box.hi.array() < target_box.lo.array()).any())
    return depth > 0.0 ? -depth : gap;
  if (!grids->surface) grids->surface.emplace(target.model->mesh);
  const SegmentGrid& surface = *grids->surface;
  for (const auto& e : Edges(mover.model->mesh)) {
    const std::vector<double> s = surface.Crossings(at[e[0]], at[e[1]]);
    for (std::size_t k = 0; k + 1 < s.size(); ++k) probe(at[e[0]] + 0.5 * (s[k] + s[k + 1]) * (at[e[1]] - at[e[0]]));
  }
  return depth > 0.0 ? -depth : gap;
}

// the way a moves relative to b: relative velocity, else the line between the CGs
Vec3 ClosingDirection(const RigidState& a, const RigidState& b) {
  const Vec3 v = a.velocity - b.velocity;
  if (v.norm() > 0.0) return v.normalized();
  const Vec3 r = b.position - a.position;
  return r.norm() > 0.0 ? r.normalized() : Vec3(1, 0, 0);
}

double Diagonal(const BodyModel& m) {
  const MeshStats s = ComputeStats(m.mesh);
  return (s.max - s.min).norm();
}

// gap (or overlap) of a against b along the grids' direction d, both ways (b's vertices move along -d
// against a): the deeper overlap, or the nearer contact
double TwoWayGap(const PosedBody& a, const PosedBody& b, double length, TargetGrids* grids_a, TargetGrids* grids_b) {
  return std::min(DirectedGap(a, b, length, grids_b), DirectedGap(b, a, length, grids_a));
}

PairPlacement MeasurePair(const std::vector<PosedBody>& bodies, int a, int b, const Vec3& d) {
  const double length = (bodies[a].pose->position - bodies[b].pose->position).norm() + Diagonal(*bodies[a].model) +
                        Diagonal(*bodies[b].model);
  TargetGrids grids_a(bodies[a], -d), grids_b(bodies[b], d);
  PairPlacement p;
  p.a = a;
  p.b = b;
  p.direction = d;
  p.gap = TwoWayGap(bodies[a], bodies[b], length, &grids_a, &grids_b);
  p.meet = p.gap != kNone;
  if (!p.meet) p.gap = 0.0;
  // the vertices' gap, less the overlap the edges then show with a moved there: an edge meets an edge
  // first (a car's rounded nose onto a box's corner, each edge passing the other's face with no vertex
  // of either meeting one: 6 in on coarse meshes, and a body placed at contact was refused), corrected
  // until none is left
  RigidState moved = *bodies[a].pose;
  const PosedBody touching{bodies[a].model, &moved, bodies[a].rotation};
  for (int k = 0; k < kTouchCorrections && p.gap > 0.0; ++k) {
    moved.position = bodies[a].pose->position + p.gap * d;
    const double overlap = -TwoWayGap(touching, bodies[b], length, &grids_a, &grids_b);
    if (!(overlap > kSegmentSlack * (1.0 + length))) break;
    p.gap -= overlap;
  }
  return p;
}

std::vector<PosedBody> Pose(const Scenario& scenario, const std::vector<std::shared_ptr<const BodyModel>>& models) {
  std::vector<PosedBody> bodies;
  for (std::size_t i = 0; i < models.size(); ++i) {
    const RigidState& pose = scenario.bodies[i].initial;
    bodies.push_back(PosedBody{models[i].get(), &pose, pose.Rotation()});
  }
  return bodies;
}

// moves body i along its velocity relative to the named body until `gap` remains
void PlaceAtContact(Scenario* scenario, int i, const std::vector<PosedBody>& bodies) {
  BodySpec& body = scenario->bodies[i];
  const std::string field = "bodies[" + std::to_string(i) + "].initial.place_at_contact";
  const int other = body.place_at_contact->with;
  const Vec3 v = body.initial.velocity - scenario->bodies[other].initial.velocity;
  if (!(v.norm() > 0.0))
    throw InputError(scenario->file, field, "needs a velocity relative to \"" + scenario->bodies[other].name +
                                                "\" to move along; this body has none");
  const PairPlacement p = MeasurePair(bodies, i, other, v.normalized());
  if (!p.meet)
    throw InputError(scenario->file, field, "moving along its velocity, \"" + body.name + "\" never meets \"" +
                                                scenario->bodies[other].name + "\": check the positions and heading");
  body.initial.position += (p.gap - body.place_at_contact->gap) * p.direction;
}

}  // namespace

std::vector<PairPlacement> MeasurePlacements(const Scenario& scenario,
                                             const std::vector<std::shared_ptr<const BodyModel>>& models) {
  const std::vector<PosedBody> bodies = Pose(scenario, models);
  std::vector<PairPlacement> placements;
  for (int a = 0; a < static_cast<int>(bodies.size()); ++a)
    for (int b = a + 1; b < static_cast<int>(bodies.size()); ++b)
      placements.push_back(MeasurePair(bodies, a, b, ClosingDirection(*bodies[a].pose, *bodies[b].pose)));
  return placements;
}

std::vector<PairPlacement> PlaceBodies(Scenario* scenario, const std::vector<std::shared_ptr<const BodyModel>>& models) {
  // bodies placed at contact, in scenario order (each against the poses so far)
  for (int i = 0; i < static_cast<int>(scenario->bodies.size()); ++i)
    if (scenario->bodies[i].place_at_contact) PlaceAtContact(scenario, i, Pose(*scenario, models));
  // every pair: an overlap beyond the contact tolerance is refused unless allowed
  const std::vector<PairPlacement> placements = MeasurePlacements(*scenario, models);
  for (const PairPlacement& p : placements) {
    const double depth = -p.gap;
    if (!p.meet || depth <= scenario->contact.contact_tolerance) continue;
    const std::string names = "\"" + scenario->bodies[p.a].name + "\" and \"" + scenario->bodies[p.b].name + "\"";
    const std::string what = names + " overlap by " + LengthText(scenario->units, depth) + " at t = 0";
    if (!scenario->allow_initial_overlap)
      throw InputError(scenario->file, "bodies[" + std::to_string(p.b) + "].initial.position",
                       what + " (deeper than the contact tolerance): move them apart, use \"place_at_contact\", or "
                              "set \"allow_initial_overlap\": true");
    scenario->warnings.push_back(
        {"initial_overlap", "allow_initial_overlap",
         what + ": an overlap within contact.toofar_maximum is pushed out in the first steps with energy that is not "
                "physical; a deeper one is not found by the search and the bodies may pass through each other"});
  }
  return placements;
}

}  // namespace dymesh
