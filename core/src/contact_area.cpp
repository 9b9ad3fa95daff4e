#include "dymesh/core/contact_area.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "dymesh/core/geometry.h"
#include "dymesh/core/mesh.h"

namespace dymesh {
namespace {

// the clip's linear fields: the depth below the master's tangent plane, and its sharp edges
constexpr int kMaxFields = 1 + kMaxMasterEdges;

// values of the clip fields at a triangle's corners, corner 0 being the node's
using CornerValues = std::array<double, 3>;

// a convex polygon in a triangle's reference coordinates (corner 0 at (0,0), 1 at (1,0), 2 at (0,1)),
// carrying the clip fields' values at its vertices
struct ClipPolygon {
  int n = 0;
  double x[3 + kMaxFields], y[3 + kMaxFields], f[3 + kMaxFields][kMaxFields];
};

// keeps the part of `p` where field k >= 0 (Sutherland-Hodgman, one half-plane); the fields are
// linear, so interpolating them along an edge is exact
ClipPolygon ClipToField(const ClipPolygon& p, int k, int fields) {
  ClipPolygon out;
  auto keep = [&](int i, int j, double s) {
    out.x[out.n] = p.x[i] + s * (p.x[j] - p.x[i]);
    out.y[out.n] = p.y[i] + s * (p.y[j] - p.y[i]);
    for (int g = 0; g < fields; ++g) out.f[out.n][g] = p.f[i][g] + s * (p.f[j][g] - p.f[i][g]);
    ++out.n;
  };
  for (int i = 0; i < p.n; ++i) {
    const int j = (i + 1) % p.n;
    if (p.f[i][k] >= 0.0) {
      out.x[out.n] = p.x[i], out.y[out.n] = p.y[i];
      std::copy(p.f[i], p.f[i] + fields, out.f[out.n]);
      ++out.n;
    }
    if ((p.f[i][k] >= 0.0) != (p.f[j][k] >= 0.0)) keep(i, j, p.f[i][k] / (p.f[i][k] - p.f[j][k]));
  }
  return out;
}

// Integrals of the three corners' barycentric weights over the part of a triangle where every field
// is >= 0, as fractions of the triangle's area (1/3 each when all of it is)
CornerValues CornerSharesWhere(const CornerValues* values, int fields) {
  ClipPolygon p;
  p.n = 3;
  const double x[3] = {0.0, 1.0, 0.0}, y[3] = {0.0, 0.0, 1.0};
  for (int i = 0; i < 3; ++i) {
    p.x[i] = x[i], p.y[i] = y[i];
    for (int g = 0; g < fields; ++g) p.f[i][g] = values[g][i];
  }
  // wholly inside a field leaves the polygon as it is; wholly outside one leaves nothing
  bool clipped = false;
  for (int k = 0; k < fields; ++k) {
    int inside = 0;
    for (int i = 0; i < p.n; ++i) inside += p.f[i][k] >= 0.0;
    if (inside == 0) return {0.0, 0.0, 0.0};
    if (inside == p.n) continue;
    p = ClipToField(p, k, fields);
    clipped = true;
  }
  if (!clipped) return {1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0};
  // integrate lambda0 = 1 - x - y, lambda1 = x, lambda2 = y over the clipped polygon (a fan of
  // triangles: area x mean weight), over the area 1/2
  CornerValues integral = {0.0, 0.0, 0.0};
  for (int i = 1; i + 1 < p.n; ++i) {
    const double ax = p.x[i] - p.x[0], ay = p.y[i] - p.y[0], bx = p.x[i + 1] - p.x[0], by = p.y[i + 1] - p.y[0];
    const double area = 0.5 * std::abs(ax * by - bx * ay);
    const double sum_x = p.x[0] + p.x[i] + p.x[i + 1], sum_y = p.y[0] + p.y[i] + p.y[i + 1];
    integral[0] += area * (3.0 - sum_x - sum_y) / 3.0;
    integral[1] += area * sum_x / 3.0;
    integral[2] += area * sum_y / 3.0;
  }
  for (double& share : integral) share /= 0.5;
  return integral;
}

// the node's (corner 0's) part of a face's pressed area from its corners' shares: its own, and an
// equal part of each corner's that lies beyond the master's edges (that corner meets nothing, so the
// pressed part of its share is carried by the corners that do: a node on a post, its neighbours
// beside it, carries the post's whole width)
double NodeShare(const CornerValues& share, const std::array<bool, 3>& reached) {
  const int count = reached[0] + reached[1] + reached[2];
  if (count == 3) return share[0];
  double own = share[0];
  for (int c = 1; c < 3; ++c)
    if (!reached[c]) own += share[c] / count;
  return own;
}

// distance from the origin to the segment a-b (points in a plane through the origin)
double DistanceToSegment(const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp(-a.dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + t * ab).norm();
}

}  // namespace

std::vector<SharpEdge> SharpEdgesOf(const TriMesh& mesh, const VertexTriangles& adjacency) {
  std::vector<SharpEdge> sharp;
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    const auto& tri = mesh.triangles[t];
    const Vec3 cross = TriangleCross(mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]]);
    if (!(cross.squaredNorm() > 0.0)) continue;  // degenerate: no side
    const Vec3 normal = cross.normalized();
    for (int e = 0; e < 3; ++e) {
      const int from = tri[e], to = tri[(e + 1) % 3];
      const int across = TriangleAcross(mesh, adjacency, t, from, to);
      if (across >= 0) {
        const auto& other = mesh.triangles[across];
        const Vec3 other_cross = TriangleCross(mesh.vertices[other[0]], mesh.vertices[other[1]], mesh.vertices[other[2]]);
        if (other_cross.squaredNorm() > 0.0 && normal.dot(other_cross.normalized()) > kSharpEdgeCosine) continue;
      }
      // the in-plane direction across the edge toward the face's third corner
      const Vec3& a = mesh.vertices[from];
      const Vec3 along = (mesh.vertices[to] - a).normalized();
      const Vec3 third = mesh.vertices[tri[(e + 2) % 3]] - a;
      sharp.push_back({a, mesh.vertices[to], normal, (third - third.dot(along) * along).normalized()});
    }
  }
  return sharp;
}

void EdgesRoundContact(const std::vector<SharpEdge>& sharp, const Vec3& contact, const Vec3& normal, double reach,
                       std::vector<MasterEdge>* edges) {
  // the edges of faces turned toward the contact, seen along its normal, within reach: nearest first
  // (ties by their order in `sharp`)
  std::vector<std::pair<double, int>> near;
  for (int i = 0; i < static_cast<int>(sharp.size()); ++i) {
    const SharpEdge& e = sharp[i];
    if (!(e.normal.dot(normal) > 0.0)) continue;
    const double distance = DistanceToSegment(AlongSurface(e.a - contact, normal), AlongSurface(e.b - contact, normal));
    if (distance <= reach) near.emplace_back(distance, i);
  }
  std::sort(near.begin(), near.end());
  edges->clear();
  for (const auto& [distance, i] : near) {
    const SharpEdge& e = sharp[i];
    Vec3 inward = normal.cross(e.b - e.a);
    if (!(inward.squaredNorm() > 0.0)) continue;  // an edge along the normal bounds nothing seen along it
    inward.normalize();
    if (inward.dot(e.into) < 0.0) inward = -inward;
    // a straight edge cut into several faces' edges is one line
    const bool known = std::any_of(edges->begin(), edges->end(), [&](const MasterEdge& o) {
      return o.inward.dot(inward) > 1.0 - 1e-9 && std::abs((e.a - o.point).dot(o.inward)) < 1e-9;
    });
    if (known) continue;
    edges->push_back({e.a, inward});
    if (static_cast<int>(edges->size()) == kMaxMasterEdges) return;
  }
}

double ContactNodeArea(const BodyModel& model, const BodyState& s, int v, const Vec3& normal, double depth,
                       const std::vector<MasterEdge>& edges) {
  // how deep each rest (uncrushed) corner lies below the master's tangent plane at the contact: the
  // plane lies `depth` beyond v's current position along the master's outward normal
  const auto& rest = model.mesh.vertices;
  auto rest_depth = [&](int u) { return depth + (s.vertices[v] - rest[u]).dot(normal); };
  const int edge_count = std::min(static_cast<int>(edges.size()), kMaxMasterEdges);
  const auto& adj = model.vertex_triangles;
  double area = 0.0;
  for (int k = adj.offsets[v]; k < adj.offsets[v + 1]; ++k) {
    const int t = adj.ids[k];
    // only faces turned toward the master (outward normal against its outward normal) carry pressure
    const double facing = -s.tri_normal[t].dot(normal);
    if (facing <= 0.0) continue;
    // v's share of the face where its rest shape overlaps the master (a third of a face wholly inside),
    // within the master's sharp edges
    const auto& tri = model.mesh.triangles[t];
    const int at = CornerOf(tri, v);
    const std::array<int, 3> corner = {tri[at], tri[(at + 1) % 3], tri[(at + 2) % 3]};
    std::array<CornerValues, kMaxFields> fields;
    fields[0] = {rest_depth(corner[0]), rest_depth(corner[1]), rest_depth(corner[2])};
    std::array<bool, 3> inside = {true, true, true};
    for (int e = 0; e < edge_count; ++e)
      for (int i = 0; i < 3; ++i) {
        fields[1 + e][i] = (rest[corner[i]] - edges[e].point).dot(edges[e].inward);
        inside[i] = inside[i] && fields[1 + e][i] >= 0.0;
      }
    inside[0] = true;  // v meets the master
    area += s.tri_area[t] * facing * NodeShare(CornerSharesWhere(fields.data(), 1 + edge_count), inside);
  }
  return area;
}

}  // namespace dymesh
