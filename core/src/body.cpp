#include "dymesh/core/body.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "dymesh/core/parallel.h"

namespace dymesh {

namespace {

// which corner (0, 1, 2) of triangle `tri` vertex v is
int CornerOf(const std::array<int, 3>& tri, int v) { return tri[0] == v ? 0 : tri[1] == v ? 1 : 2; }

// rest angle of triangle t at its corner v over its rest area [rad/m^2] (0 for a degenerate one)
double RestAnglePerArea(const BodyModel& model, int t, int v) {
  const auto& tri = model.mesh.triangles[t];
  const auto& rest = model.mesh.vertices;
  const int i = CornerOf(tri, v);
  const Vec3 a = rest[tri[(i + 1) % 3]] - rest[v];
  const Vec3 b = rest[tri[(i + 2) % 3]] - rest[v];
  const double twice_area = a.cross(b).norm();
  return twice_area > 0.0 ? std::atan2(twice_area, a.dot(b)) / (0.5 * twice_area) : 0.0;
}

// unit mean of the triangle normals around v, each weighted by its current area times weight(t)
template <class Weight>
Vec3 MeanNormal(const BodyModel& model, const BodyState& s, int v, Weight weight) {
  const auto& adj = model.vertex_triangles;
  Vec3 sum = Vec3::Zero();
  for (int k = adj.offsets[v]; k < adj.offsets[v + 1]; ++k) {
    const int t = adj.ids[k];
    sum += (weight(t) * s.tri_area[t]) * s.tri_normal[t];
  }
  const double len = sum.norm();
  return len > 0.0 ? Vec3(sum / len) : Vec3::Zero();
}

// UpdateTriangles' marks on a vertex: it moved; its normal is listed for recomputing
constexpr std::uint8_t kMovedMark = 1, kStaleMark = 2;

// current area and unit outward normal of triangle t
void UpdateTriangle(const BodyModel& model, int t, BodyState* s) {
  const auto& tri = model.mesh.triangles[t];
  const Vec3 cross = TriangleCross(s->vertices[tri[0]], s->vertices[tri[1]], s->vertices[tri[2]]);
  const double twice_area = cross.norm();
  s->tri_area[t] = 0.5 * twice_area;
  s->tri_normal[t] = twice_area > 0.0 ? Vec3(cross / twice_area) : Vec3::Zero();
}

}  // namespace

BodyModel MakeBodyModel(std::string name, TriMesh mesh, const std::array<Stiffness, kBodySurfaceCount>& stiffness,
                        double mass, const Mat3& inertia, double restitution, double friction, bool rigid) {
  BodyModel m;
  m.name = std::move(name);
  m.mesh = std::move(mesh);
  m.vertex_triangles = BuildVertexTriangles(m.mesh);
  m.stiffness = stiffness;
  m.mass = mass;
  m.inertia = inertia;
  m.restitution = restitution;
  m.friction = friction;
  m.rigid = rigid;
  m.median_edge = MedianEdgeLength(m.mesh);
  // rest area vectors (the conforming contact normal reads them for every located node)
  m.rest_area.reserve(m.mesh.triangles.size());
  for (const auto& tri : m.mesh.triangles)
    m.rest_area.push_back(
        TriangleCross(m.mesh.vertices[tri[0]], m.mesh.vertices[tri[1]], m.mesh.vertices[tri[2]]).cast<float>());
  // surface class of each vertex from its rest outward normal (DefineVertStiffness)
  const BodyState rest = MakeBodyState(m, RigidState{});
  m.surface.resize(m.mesh.vertices.size());
  for (size_t v = 0; v < m.surface.size(); ++v) {
    m.surface[v] = ClassifySurface(rest.vertex_normal[v]);
  }
  return m;
}

BodyState MakeBodyState(const BodyModel& model, const RigidState& rigid) {
  const size_t nv = model.mesh.vertices.size(), nt = model.mesh.triangles.size();
  BodyState s;
  s.rigid = rigid;
  s.vertices = model.mesh.vertices;
  s.delta.assign(nv, Vec3::Zero());
  s.delta_max.assign(nv, 0.0);
  s.unload.assign(nv, UnloadState::kCannotUnload);
  s.node_force.assign(nv, 0.0);
  s.node_area.assign(nv, 0.0);
  s.update_step.assign(nv, -1);
  s.step_start_deflection.assign(nv, 0.0);
  s.contact_normal.assign(nv, Vec3::Zero());
  s.vertex_normal.assign(nv, Vec3::Zero());
  s.update_mark.assign(nv, 0);
  s.tri_normal.assign(nt, Vec3::Zero());
  s.tri_area.assign(nt, 0.0);
  // triangle normals and areas, and vertex normals, of the undamaged mesh
  std::vector<int> all(nv);
  for (size_t v = 0; v < nv; ++v) all[v] = static_cast<int>(v);
  UpdateTriangles(model, all, &s);
  return s;
}

void UpdateTriangles(const BodyModel& model, const std::vector<int>& vertices, BodyState* s) {
  const auto& adj = model.vertex_triangles;
  auto& mark = s->update_mark;
  // the moved vertices marked (each listed once: a triangle is recomputed by one chunk)
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    if (mark[vertices[i]] & kMovedMark) {
      for (std::size_t j = 0; j < i; ++j) mark[vertices[j]] = 0;
      throw std::invalid_argument("UpdateTriangles: vertex listed twice");
    }
    mark[vertices[i]] |= kMovedMark;
  }
  // every corner of a triangle round them, listed once: its normal is recomputed
  std::vector<int> corners;
  for (int v : vertices) {
    for (int k = adj.offsets[v]; k < adj.offsets[v + 1]; ++k) {
      for (int corner : model.mesh.triangles[adj.ids[k]]) {
        if (mark[corner] & kStaleMark) continue;
        mark[corner] |= kStaleMark;
        corners.push_back(corner);
      }
    }
  }
  // each triangle round them once, at its lowest moved corner, in parallel (each writes its own slots)
  ForEachChunk(vertices.size(), [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const int v = vertices[i];
      for (int k = adj.offsets[v]; k < adj.offsets[v + 1]; ++k) {
        const int t = adj.ids[k];
        const auto& tri = model.mesh.triangles[t];
        auto moved_before = [&](int c) { return c < v && (mark[c] & kMovedMark); };
        if (std::none_of(tri.begin(), tri.end(), moved_before)) UpdateTriangle(model, t, s);
      }
    }
  });
  // then the corners' normals from those triangles, in parallel
  ForEachChunk(corners.size(), [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) s->vertex_normal[corners[i]] = AreaWeightedNormal(model, *s, corners[i]);
  });
  for (int v : vertices) mark[v] = 0;
  for (int c : corners) mark[c] = 0;
}

Vec3 AreaWeightedNormal(const BodyModel& model, const BodyState& s, int v) {
  return MeanNormal(model, s, v, [](int) { return 1.0; });
}

Vec3 LocalAverageNormal(const BodyModel& model, const BodyState& s, int v) {
  // spec §2 USE_LOCAL_AVERAGE_NORMAL: at rest each face counts by its angle at the node, so a node
  // on a box's edge points halfway between the two faces however either is cut (by area, a
  // strip-meshed side's long triangles turned it sideways); a crushed face counts by the share of its
  // rest area it keeps. Computed per call from the rest mesh (only this search method asks; kept, it
  // would cost 24 bytes per triangle)
  return MeanNormal(model, s, v, [&](int t) { return RestAnglePerArea(model, t, v); });
}

namespace {

// Integral of corner 0's barycentric weight over the part of a triangle where the linear field psi
// (psi0..psi2 at its corners) is positive, as a fraction of the triangle's area (1/3 when all of it is)
double InsideShareOfCorner0(double psi0, double psi1, double psi2) {
  // wholly inside or wholly outside (most faces): the clip below gives exactly these
  if (psi0 >= 0.0 && psi1 >= 0.0 && psi2 >= 0.0) return 1.0 / 3.0;
  if (psi0 < 0.0 && psi1 < 0.0 && psi2 < 0.0) return 0.0;
  // clip the reference triangle (0,0) (1,0) (0,1) to psi >= 0 (Sutherland-Hodgman, one half-plane)
  const double x[3] = {0.0, 1.0, 0.0}, y[3] = {0.0, 0.0, 1.0}, psi[3] = {psi0, psi1, psi2};
  double px[4], py[4];
  int n = 0;
  auto keep = [&](double kx, double ky) { px[n] = kx, py[n] = ky, ++n; };
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (psi[i] >= 0.0) keep(x[i], y[i]);
    if ((psi[i] >= 0.0) != (psi[j] >= 0.0)) {
      const double s = psi[i] / (psi[i] - psi[j]);
      keep(x[i] + s * (x[j] - x[i]), y[i] + s * (y[j] - y[i]));
    }
  }
  // integrate lambda0 = 1 - x - y over the clipped polygon (a fan of triangles: area x mean lambda0),
  // over the area 1/2
  double integral = 0.0;
  for (int i = 1; i + 1 < n; ++i) {
    const double ax = px[i] - px[0], ay = py[i] - py[0], bx = px[i + 1] - px[0], by = py[i + 1] - py[0];
    const double area = 0.5 * std::abs(ax * by - bx * ay);
    integral += area * (3.0 - (px[0] + px[i] + px[i + 1]) - (py[0] + py[i] + py[i + 1])) / 3.0;
  }
  return integral / 0.5;
}

}  // namespace

double ContactNodeArea(const BodyModel& model, const BodyState& s, int v, const Vec3& normal, double depth) {
  // how deep each rest (uncrushed) corner lies below the master's tangent plane at the contact: the
  // plane lies `depth` beyond v's current position along the master's outward normal
  auto rest_depth = [&](int u) { return depth + (s.vertices[v] - model.mesh.vertices[u]).dot(normal); };
  const auto& adj = model.vertex_triangles;
  double area = 0.0;
  for (int k = adj.offsets[v]; k < adj.offsets[v + 1]; ++k) {
    const int t = adj.ids[k];
    // only faces turned toward the master (outward normal against its outward normal) carry pressure
    const double facing = -s.tri_normal[t].dot(normal);
    if (facing <= 0.0) continue;
    // v's share of the face where its rest shape overlaps the master (a third of a face wholly inside)
    const auto& tri = model.mesh.triangles[t];
    const int at = CornerOf(tri, v);
    const double share = InsideShareOfCorner0(rest_depth(tri[at]), rest_depth(tri[(at + 1) % 3]),
                                              rest_depth(tri[(at + 2) % 3]));
    area += s.tri_area[t] * facing * share;
  }
  return area;
}

}  // namespace dymesh
