#pragma once
#include <vector>

#include "dymesh/core/body.h"

/// The contact area A_v of spec §3: the part of a slave node's surrounding faces that a master presses.
namespace dymesh {

/// A sharp edge of a rigid master's surface that bounds the part of it round a contact (slave frame):
/// a point on the edge and the direction across it, seen along the contact normal, toward that part.
struct MasterEdge {
  Vec3 point{0, 0, 0};
  Vec3 inward{0, 0, 0};
};

/// The most sharp edges a contact area is bounded by (a post's front has four).
inline constexpr int kMaxMasterEdges = 8;

/// A sharp edge of a body's surface as seen from one of its two faces (body frame): its ends, that
/// face's outward normal, and the direction in the face's plane across the edge into the face.
struct SharpEdge {
  Vec3 a{0, 0, 0}, b{0, 0, 0};
  Vec3 normal{0, 0, 0};
  Vec3 into{0, 0, 0};
};

/// Cosine of the turn between two faces beyond which their edge is sharp (45 deg: a post's corner
/// is, a round pole's facets are not).
inline constexpr double kSharpEdgeCosine = 0.7071067811865476;

/// Every sharp edge of a mesh, once from each of its faces: edges whose two faces turn by more than
/// kSharpEdgeCosine, and open edges (one face).
std::vector<SharpEdge> SharpEdgesOf(const TriMesh& mesh, const VertexTriangles& adjacency);

/// The sharp edges that bound the surface round a contact at `contact` (outward normal `normal`, the
/// frame of `sharp`): those of faces turned toward the contact that come within `reach` of it seen
/// along the normal, each straight line once, nearest first, at most kMaxMasterEdges. `inward` is
/// unit, across the line toward its face, perpendicular to `normal`.
void EdgesRoundContact(const std::vector<SharpEdge>& sharp, const Vec3& contact, const Vec3& normal, double reach,
                       std::vector<MasterEdge>* edges);

/// Contact area A_v of spec §3 for slave vertex v pressed against a master whose outward normal at
/// the contact is `normal` (body frame), v lying `depth` inside it: v's share (a third of a face wholly
/// in contact) of each surrounding face turned toward the master, projected on the contact plane, and
/// only over the part of the face whose rest shape overlaps the master's tangent plane there. A face
/// reaching far out of the contact (a long side panel behind a crushed corner) counts only where it
/// meets the master, so the area converges as the mesh is refined.
///
/// `edges` (at most kMaxMasterEdges), a rigid master's sharp edges round the contact, also bound the
/// tangent plane: a face counts only where its rest shape, seen along `normal`, lies inside them, and
/// what lies inside them of a neighbour's share, where that neighbour lies outside, is v's (that
/// neighbour meets nothing): a node on a post narrower than the node's faces carries the post's width.
double ContactNodeArea(const BodyModel& model, const BodyState& state, int v, const Vec3& normal, double depth,
                       const std::vector<MasterEdge>& edges = {});

}  // namespace dymesh
