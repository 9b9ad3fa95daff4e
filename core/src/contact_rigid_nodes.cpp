#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "contact_pass_frame.h"
#include "dymesh/core/geometry.h"
#include "dymesh/core/node_force.h"
#include "dymesh/core/parallel.h"

namespace dymesh {
namespace {

// Tikhonov weight of the face fit, relative to the mean diagonal of its normal equations: small
// enough to leave a fit over three or more spread nodes as it is, large enough to make a singular
// fit (one node, nodes in a line) the least push
constexpr double kFitRegularisation = 1e-6;

// the least share of a face its free corners carry at a crossing rigid node for that node to push it:
// the half of the face nearer them (nearer a held corner, the held node's own contact carries it)
constexpr double kFreeShareToPush = 0.5;

// the least speed at which a rigid node closing on a face crosses it within the step: slower, the depth
// it lies behind the face is older (what the body's own node held there until it came to rest: pushed
// then, the box resting against the round pole crushed 0.6 in past its stop, 12.6 % over the column
// closed form). It is FRICTION_NULL_BAND's default (spec §7), below which sliding counts as none
constexpr double kLeastCrossingSpeed = 1.0 * units::kInch;  // [m/s]

// a rigid node that crossed a deformable face in the last step (deformable frame)
struct Crossing {
  int node = 0;          // rigid vertex
  int triangle = 0;      // deformable face it lies behind
  double depth = 0.0;    // [m] behind the face, along its normal
  Vec3 point{0, 0, 0};   // the rigid node
  Vec3 normal{0, 0, 0};  // the face's outward normal, unit
  std::array<double, 3> weight{};  // the node's place on the face (barycentric, clamped to it)
};

// pushes of a face's three corners along its normal [m] that move it at the crossing nodes
// [first, last) by their depths, least squares (Tikhonov-regularised: with fewer than three nodes,
// or nodes in a line, the least push); a held corner (its own node meets the rigid surface: its
// contact carries it) takes none, none pulls a corner out toward the rigid body, and none goes
// beyond the deepest node (moving the whole face by that clears every node: a plane fitted to nodes
// bunched at one edge must not tip its far corner through the body, 250 in on the p406's pole runs)
std::array<double, 3> FacePush(const std::vector<Crossing>& crossings, std::size_t first, std::size_t last,
                               const std::array<bool, 3>& held) {
  Mat3 normal = Mat3::Zero();
  Vec3 right = Vec3::Zero();
  double deepest = 0.0;
  for (std::size_t i = first; i < last; ++i) {
    const Vec3 w(crossings[i].weight[0], crossings[i].weight[1], crossings[i].weight[2]);
    normal += w * w.transpose();
    right += crossings[i].depth * w;
    deepest = std::max(deepest, crossings[i].depth);
  }
  normal += kFitRegularisation * (normal.trace() / 3.0) * Mat3::Identity();
  // a held corner's push is fixed at zero: its row and column leave the fit
  for (int k = 0; k < 3; ++k) {
    if (!held[k]) continue;
    normal.row(k).setZero();
    normal.col(k).setZero();
    normal(k, k) = 1.0;
    right[k] = 0.0;
  }
  const Vec3 push = normal.ldlt().solve(right).cwiseMax(0.0).cwiseMin(deepest);
  return {push[0], push[1], push[2]};
}

// the end of the run of crossings on the face of crossings[first] (crossings sorted by face)
std::size_t FaceEnd(const std::vector<Crossing>& crossings, std::size_t first) {
  std::size_t last = first;
  while (last < crossings.size() && crossings[last].triangle == crossings[first].triangle) ++last;
  return last;
}

// the share of a face at a crossing node that its free corners carry (barycentric weights)
template <typename FreeCorner>
double FreeShare(const Crossing& c, const std::array<int, 3>& tri, const FreeCorner& free_corner) {
  double share = 0.0;
  for (int corner = 0; corner < 3; ++corner) share += free_corner(tri[corner]) ? c.weight[corner] : 0.0;
  return share;
}

// the areas the rigid nodes crossing one face [first, last) press it with: each its own contact area
// (spec §3 A_v, in the rigid body's frame) times the face's share its free corners carry (a held
// corner's own contact carries its barycentric share: its node area counts the face so), all
// together at most the free corners' part of the face (a coarse wall's node spans more than the face)
template <typename FreeCorner, typename OwnArea>
std::vector<double> PressedAreas(const std::vector<Crossing>& crossings, std::size_t first, std::size_t last,
                                 const std::array<int, 3>& tri, double face_area, const FreeCorner& free_corner,
                                 const OwnArea& own_area) {
  int free_corners = 0;
  for (int v : tri) free_corners += free_corner(v) ? 1 : 0;
  std::vector<double> areas;
  double total = 0.0;
  for (std::size_t i = first; i < last; ++i) {
    const Crossing& c = crossings[i];
    areas.push_back(FreeShare(c, tri, free_corner) * own_area(c));
    total += areas.back();
  }
  const double free_part = face_area * free_corners / 3.0;
  if (total > free_part) {
    for (double& area : areas) area *= free_part / total;
  }
  return areas;
}

}  // namespace

ContactEngine::PassSums ContactEngine::PushFacesOffRigidNodes(int rigid, int deformable, const EngagedNodes& engaged,
                                                             double dt, ContactDiagnostics* diag) {
  PassSums sums;
  sums.master = deformable;
  sums.slave = rigid;
  BodyState& s = states_[deformable];
  const BodyModel& m = *models_[deformable];
  const PassFrame f = FrameOf(deformable, rigid);
  const std::vector<int> candidates = CullCandidates(f, deformable, rigid, EngagedNodes{});
  if (candidates.empty()) return sums;
  locators_[deformable]->Prepare(rigid, step_index_, candidates,
                                 [&](int v) { return f.ToMaster(f.slave->vertices[v]); });

  // spec §2 Location with the rigid body's nodes as slaves: a node that crossed a face while closing on
  // it (at least kLeastCrossingSpeed; no deeper than a step's motion plus TOOFAR_MARGIN: a face found
  // deeper was passed before, an inner layer of a display mesh), on the half of a face nearer its free
  // corners (barycentric weight at least 1/2). A corner is held where the deformable body's own node
  // meets the rigid surface: touching it, or having found it closing on it or lies behind it; its own
  // contact carries the load round it (pushing the free corners to clear a node near a held one crushed
  // the p406 786 in on the round pole). A face with held and free corners is still pushed where it spans
  // beyond the held ones: a node column on a post's edge slid off it and the post went through the
  // faces between that column and the next (delta-V 0.18 of 10 mph with the post 0.001 in off the column)
  auto free_corner = [&](int v) {
    return !std::binary_search(engaged.touching.begin(), engaged.touching.end(), v) &&
           !std::binary_search(engaged.located.begin(), engaged.located.end(), v);
  };
  chunks_.resize(std::max(chunks_.size(), ChunkCount(candidates.size())));
  std::vector<std::vector<Crossing>> found(ChunkCount(candidates.size()));
  ForEachChunk(candidates.size(), [&](std::size_t chunk, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      Located hit;
      if (!LocateNode(f, candidates[i], false, nullptr, &chunks_[chunk].scratch, &hit)) continue;
      const double closing = -hit.rel_velocity.dot(hit.normal);
      if (hit.depth <= options_.contact_tolerance || closing < kLeastCrossingSpeed) continue;
      if (hit.depth > hit.TooFar(dt, options_.toofar_margin)) continue;
      const auto& tri = m.mesh.triangles[hit.triangle];
      Crossing c{candidates[i], hit.triangle, hit.depth, f.ToMaster(f.slave->vertices[candidates[i]]), hit.normal};
      c.weight = ClampedBarycentric(c.point, s.vertices[tri[0]], s.vertices[tri[1]], s.vertices[tri[2]]);
      if (FreeShare(c, tri, free_corner) >= kFreeShareToPush) found[chunk].push_back(c);
    }
  });
  std::vector<Crossing> crossings;
  for (const auto& list : found) crossings.insert(crossings.end(), list.begin(), list.end());
  if (crossings.empty()) return sums;

  // each face's corner pushes, along its normal, that move it at its crossing nodes by their depths
  // in the least-squares sense (a face parallel to the rigid surface moves parallel, one node alone
  // gets the least push that clears it); a corner shared by faces takes the largest; the rigid side
  // takes none (determinism: faces in index order, nodes in index order within a face)
  std::sort(crossings.begin(), crossings.end(), [](const Crossing& x, const Crossing& y) {
    return x.triangle != y.triangle ? x.triangle < y.triangle : x.node < y.node;
  });
  std::vector<Vec3>& pending = pending_delta_[deformable];
  std::vector<int> corners;
  for (std::size_t first = 0; first < crossings.size();) {
    const std::size_t last = FaceEnd(crossings, first);
    const auto& tri = m.mesh.triangles[crossings[first].triangle];
    const std::array<double, 3> push =
        FacePush(crossings, first, last, {!free_corner(tri[0]), !free_corner(tri[1]), !free_corner(tri[2])});
    for (int k = 0; k < 3; ++k) {
      if (!(push[k] > 0.0)) continue;
      const Vec3 along = -push[k] * crossings[first].normal;
      const int v = tri[k];
      if (std::find(corners.begin(), corners.end(), v) == corners.end()) {
        corners.push_back(v);
        pending[v] = along;
      } else if (along.squaredNorm() > pending[v].squaredNorm()) {
        pending[v] = along;
      }
    }
    first = last;
  }
  // the corners take their pushes as crush on the loading branch (spec §6), bottoming at MaxCrush
  std::sort(corners.begin(), corners.end());
  std::vector<double> before(corners.size()), peak(corners.size());
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const int v = corners[i];
    const Stiffness& k = m.VertexStiffness(v);
    before[i] = s.delta[v].norm();
    peak[i] = s.delta_max[v];
    Vec3 delta = s.delta[v] + pending[v];
    const double cap = std::max(k.max_crush, before[i]);
    if (k.max_crush > 0.0 && delta.norm() > cap) {
      delta *= cap / delta.norm();
      ++diag->max_crush_limited;
    }
    pending[v] = delta;
    s.delta_max[v] = std::max(peak[i], delta.norm());
    s.unload[v] = NextUnloadState(s.unload[v], true, delta.norm(), s.delta_max[v], m.restitution, options_);
  }
  auto crush_at = [&](const Crossing& c, bool after) {
    // the face's crush at the node: its corners' crush by the node's place (pushed corners as pushed)
    const auto& tri = m.mesh.triangles[c.triangle];
    const auto& w = c.weight;
    double crush = 0.0, top = 0.0;
    for (int k = 0; k < 3; ++k) {
      const auto at = std::lower_bound(corners.begin(), corners.end(), tri[k]);
      const bool pushed = at != corners.end() && *at == tri[k];
      const std::size_t i = static_cast<std::size_t>(at - corners.begin());
      crush += w[k] * (after && pushed ? pending[tri[k]].norm() : pushed ? before[i] : s.delta[tri[k]].norm());
      top += w[k] * (pushed ? peak[i] : s.delta_max[tri[k]]);
    }
    return std::array<double, 2>{crush, top};
  };

  // each node presses its own area with the face's law (its corners' stiffness and crush, as a
  // deformable master's face under a slave node, spec §5 note): the law's work over the face's crush
  // at the node, and the mean pressure over that crush as the force, so force times the step's
  // approach is the work booked. Both bodies are loaded at the rigid node (momentum conserved)
  auto own_area = [&](const Crossing& c) {
    const Vec3 normal_rigid = f.r_slave_to_master.transpose() * c.normal;
    return ContactNodeArea(*f.slave_model, *f.slave, c.node, normal_rigid, c.depth);
  };
  for (std::size_t first = 0; first < crossings.size();) {
    const std::size_t last = FaceEnd(crossings, first);
    const int t = crossings[first].triangle;
    const std::vector<double> areas =
        PressedAreas(crossings, first, last, m.mesh.triangles[t], s.tri_area[t], free_corner, own_area);
    const Stiffness k = CornerAverage(m, m.mesh.triangles[t]);
    for (std::size_t i = first; i < last; ++i) {
      const Crossing& c = crossings[i];
      const auto [from, top] = crush_at(c, false);
      const double to = crush_at(c, true)[0];
      if (!(to > from)) continue;
      const double work = areas[i - first] * NodeLawWork(k, from, to, top, m.restitution, options_);
      if (!std::isfinite(work) || !(work > 0.0)) continue;
      const Vec3 on_rigid = f.r_master * c.normal * (work / (to - from));
      sums.normal.Add(on_rigid, f.r_slave * f.slave->vertices[c.node], f.r_master * c.point);
      sums.law_energy += work;
      ++diag->faces_pushed;
    }
    first = last;
  }
  moved_[deformable] = std::move(corners);
  CommitPending(deformable);
  s.law_energy += sums.law_energy;
  return sums;
}

}  // namespace dymesh
