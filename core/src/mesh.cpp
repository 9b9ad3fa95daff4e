#include "dymesh/core/mesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <unordered_map>
#include <utility>

namespace dymesh {
namespace {

// integer grid cell of a point (weld hashing)
struct Cell {
  std::int64_t x, y, z;
  bool operator==(const Cell& o) const { return x == o.x && y == o.y && z == o.z; }
};

struct CellHash {
  std::size_t operator()(const Cell& c) const {
    std::uint64_t h = static_cast<std::uint64_t>(c.x) * 0x9E3779B97F4A7C15ull;
    h ^= static_cast<std::uint64_t>(c.y) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
    h ^= static_cast<std::uint64_t>(c.z) * 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
    return static_cast<std::size_t>(h);
  }
};

// an undirected edge as one sortable key (smaller index in the high half)
std::uint64_t EdgeKey(int a, int b) {
  const auto lo = static_cast<std::uint32_t>(std::min(a, b));
  const auto hi = static_cast<std::uint32_t>(std::max(a, b));
  return (static_cast<std::uint64_t>(lo) << 32) | hi;
}

// every triangle's edges between distinct vertices as sorted keys, once per use
std::vector<std::uint64_t> SortedEdgeUses(const TriMesh& mesh) {
  std::vector<std::uint64_t> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      if (t[k] != t[(k + 1) % 3]) edges.push_back(EdgeKey(t[k], t[(k + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  return edges;
}

// a triangle is degenerate when two corners share an index or its area is zero to rounding
bool IsDegenerate(const TriMesh& mesh, const std::array<int, 3>& t) {
  if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) return true;
  const Vec3& a = mesh.vertices[t[0]];
  const Vec3& b = mesh.vertices[t[1]];
  const Vec3& c = mesh.vertices[t[2]];
  const double longest_sq = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  return TriangleCross(a, b, c).norm() <= 1e-14 * longest_sq;
}

// exact-position representative map (tolerance <= 0): bit patterns of the coordinates
std::vector<int> ExactRepresentatives(const TriMesh& mesh) {
  struct Bits {
    std::uint64_t x, y, z;
    bool operator==(const Bits& o) const { return x == o.x && y == o.y && z == o.z; }
  };
  struct BitsHash {
    std::size_t operator()(const Bits& b) const {
      return CellHash{}(Cell{static_cast<std::int64_t>(b.x), static_cast<std::int64_t>(b.y),
                             static_cast<std::int64_t>(b.z)});
    }
  };
  auto bits = [](double v) {
    v += 0.0;  // -0.0 and 0.0 are the same position
    std::uint64_t u;
    std::memcpy(&u, &v, sizeof u);
    return u;
  };
  std::unordered_map<Bits, int, BitsHash> first;
  std::vector<int> rep(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vec3& p = mesh.vertices[i];
    const auto [it, inserted] = first.try_emplace(Bits{bits(p.x()), bits(p.y()), bits(p.z())}, static_cast<int>(i));
    rep[i] = it->second;
  }
  return rep;
}

// grid-hash representative map: each vertex maps to the lowest-index earlier representative within tolerance
std::vector<int> GridRepresentatives(const TriMesh& mesh, double tolerance) {
  const double inv = 1.0 / tolerance;
  auto cell_of = [inv](const Vec3& p) {
    return Cell{static_cast<std::int64_t>(std::floor(p.x() * inv)), static_cast<std::int64_t>(std::floor(p.y() * inv)),
                static_cast<std::int64_t>(std::floor(p.z() * inv))};
  };
  const double tol_sq = tolerance * tolerance;
  std::unordered_map<Cell, std::vector<int>, CellHash> grid;
  std::vector<int> rep(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vec3& p = mesh.vertices[i];
    const Cell c = cell_of(p);
    // determinism: the lowest index wins, whatever the cell visiting order
    int best = -1;
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto it = grid.find(Cell{c.x + dx, c.y + dy, c.z + dz});
          if (it == grid.end()) continue;
          for (int j : it->second)
            if ((mesh.vertices[j] - p).squaredNorm() <= tol_sq && (best < 0 || j < best)) best = j;
        }
    if (best >= 0) {
      rep[i] = best;
    } else {
      rep[i] = static_cast<int>(i);
      grid[c].push_back(static_cast<int>(i));
    }
  }
  return rep;
}

// coordinate of grid line i of n on an axis of length l (one formula, so shared edges match exactly)
double GridCoordinate(double l, int i, int n) { return -0.5 * l + l * static_cast<double>(i) / n; }

// one face of MakeBox: outward along +/- axis `a`, a (nu x nv) grid in the cyclic in-plane axes
void AddBoxFace(const double size[3], const int segments[3], int a, bool positive, TriMesh* mesh) {
  const int u = (a + 1) % 3, v = (a + 2) % 3;  // u x v = +e_a
  const int nu = segments[u], nv = segments[v];
  const double fixed = GridCoordinate(size[a], positive ? segments[a] : 0, segments[a]);
  const int base = static_cast<int>(mesh->vertices.size());
  // grid vertices, row-major in (j along v, i along u)
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      Vec3 p;
      p[a] = fixed;
      p[u] = GridCoordinate(size[u], i, nu);
      p[v] = GridCoordinate(size[v], j, nv);
      mesh->vertices.push_back(p);
    }
  // two triangles per cell, counter-clockwise seen from outside
  auto id = [&](int i, int j) { return base + j * (nu + 1) + i; };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const int p00 = id(i, j), p10 = id(i + 1, j), p11 = id(i + 1, j + 1), p01 = id(i, j + 1);
      if (positive) {
        mesh->triangles.push_back({p00, p10, p11});
        mesh->triangles.push_back({p00, p11, p01});
      } else {
        mesh->triangles.push_back({p00, p11, p10});
        mesh->triangles.push_back({p00, p01, p11});
      }
    }
}

}  // namespace

TriMesh Weld(const TriMesh& mesh, double tolerance) {
  // a tolerance below the coordinates' rounding (or none) merges identical positions only
  double max_abs = 0.0;
  for (const Vec3& p : mesh.vertices) max_abs = std::max(max_abs, p.cwiseAbs().maxCoeff());
  const bool use_grid = tolerance > 0.0 && std::isfinite(tolerance) && max_abs < 1e15 * tolerance;
  // representative of every vertex (first earlier vertex within tolerance)
  const std::vector<int> rep = use_grid ? GridRepresentatives(mesh, tolerance) : ExactRepresentatives(mesh);
  // remap triangles, dropping those whose corners collapse
  std::vector<std::array<int, 3>> triangles;
  triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    const std::array<int, 3> r{rep[t[0]], rep[t[1]], rep[t[2]]};
    if (r[0] == r[1] || r[1] == r[2] || r[2] == r[0]) continue;
    triangles.push_back(r);
  }
  // keep referenced representatives, in their original order
  std::vector<int> new_index(mesh.vertices.size(), -1);
  for (const auto& t : triangles)
    for (int v : t) new_index[v] = 0;
  TriMesh out;
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    if (new_index[i] < 0) continue;
    new_index[i] = static_cast<int>(out.vertices.size());
    out.vertices.push_back(mesh.vertices[i]);
  }
  out.triangles.reserve(triangles.size());
  for (const auto& t : triangles) out.triangles.push_back({new_index[t[0]], new_index[t[1]], new_index[t[2]]});
  return out;
}

VertexTriangles BuildVertexTriangles(const TriMesh& mesh) {
  VertexTriangles adj;
  const int n = static_cast<int>(mesh.vertices.size());
  // count triangles per vertex, then prefix sums
  adj.offsets.assign(n + 1, 0);
  for (const auto& t : mesh.triangles)
    for (int v : t) ++adj.offsets[v + 1];
  for (int v = 0; v < n; ++v) adj.offsets[v + 1] += adj.offsets[v];
  // fill in triangle order, so each vertex's list is ascending
  adj.ids.resize(adj.offsets[n]);
  std::vector<int> cursor(adj.offsets.begin(), adj.offsets.end() - 1);
  for (int ti = 0; ti < static_cast<int>(mesh.triangles.size()); ++ti)
    for (int v : mesh.triangles[ti]) adj.ids[cursor[v]++] = ti;
  return adj;
}

TriMesh Subdivide(const TriMesh& mesh) {
  TriMesh out;
  out.vertices = mesh.vertices;
  out.vertices.reserve(mesh.vertices.size() + 3 * mesh.triangles.size() / 2 + 1);
  out.triangles.reserve(4 * mesh.triangles.size());
  // one midpoint per undirected edge, created on first use
  std::unordered_map<std::uint64_t, int> midpoint;
  midpoint.reserve(3 * mesh.triangles.size() / 2 + 1);
  auto mid = [&](int a, int b) {
    const auto [it, inserted] = midpoint.try_emplace(EdgeKey(a, b), static_cast<int>(out.vertices.size()));
    if (inserted) out.vertices.push_back(0.5 * (mesh.vertices[a] + mesh.vertices[b]));
    return it->second;
  };
  // four triangles per triangle, same winding as the parent
  for (const auto& t : mesh.triangles) {
    const int ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
    out.triangles.push_back({t[0], ab, ca});
    out.triangles.push_back({ab, t[1], bc});
    out.triangles.push_back({ca, bc, t[2]});
    out.triangles.push_back({ab, bc, ca});
  }
  return out;
}

TriMesh MakeBox(double length, double width, double height, int nx, int ny, int nz) {
  // refuse impossible sizes
  if (!(length > 0.0) || !(width > 0.0) || !(height > 0.0) || !std::isfinite(length) || !std::isfinite(width) ||
      !std::isfinite(height))
    throw std::invalid_argument("MakeBox: sizes must be finite and > 0");
  if (nx < 1 || ny < 1 || nz < 1) throw std::invalid_argument("MakeBox: segments must be >= 1");
  // six faces, each a grid on the shared coordinate lines
  const double size[3] = {length, width, height};
  const int segments[3] = {nx, ny, nz};
  TriMesh mesh;
  for (int a = 0; a < 3; ++a) {
    AddBoxFace(size, segments, a, false, &mesh);
    AddBoxFace(size, segments, a, true, &mesh);
  }
  // merge the duplicated edge and corner vertices (identical by construction)
  return Weld(mesh, 1e-9 * std::sqrt(length * length + width * width + height * height));
}

double MedianEdgeLength(const TriMesh& mesh) {
  // each edge once, then the middle of its lengths
  std::vector<std::uint64_t> keys = SortedEdgeUses(mesh);
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  if (keys.empty()) return 0.0;
  std::vector<double> lengths;
  lengths.reserve(keys.size());
  for (std::uint64_t key : keys) {
    const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffu);
    lengths.push_back((mesh.vertices[a] - mesh.vertices[b]).norm());
  }
  const auto middle = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
  std::nth_element(lengths.begin(), middle, lengths.end());
  return *middle;
}

MeshStats ComputeStats(const TriMesh& mesh) {
  MeshStats s;
  s.vertices = static_cast<int>(mesh.vertices.size());
  s.triangles = static_cast<int>(mesh.triangles.size());
  // bounds
  if (!mesh.vertices.empty()) {
    s.min = s.max = mesh.vertices.front();
    for (const Vec3& p : mesh.vertices) {
      s.min = s.min.cwiseMin(p);
      s.max = s.max.cwiseMax(p);
    }
  }
  // degenerate triangles
  for (const auto& t : mesh.triangles)
    if (IsDegenerate(mesh, t)) ++s.degenerate_triangles;
  // count uses of each edge: one is open, more than two is non-manifold
  const std::vector<std::uint64_t> edges = SortedEdgeUses(mesh);
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i == 1) ++s.open_edges;
    if (j - i > 2) ++s.nonmanifold_edges;
    i = j;
  }
  return s;
}

PointBounds BoundsOf(const std::vector<Vec3>& points) {
  PointBounds b;
  for (const Vec3& p : points) {
    b.lo = b.lo.cwiseMin(p);
    b.hi = b.hi.cwiseMax(p);
  }
  return b;
}

double FarthestFromOrigin(const std::vector<Vec3>& points) {
  double farthest = 0.0;
  for (const Vec3& p : points) farthest = std::max(farthest, p.norm());
  return farthest;
}

double SignedVolume(const TriMesh& mesh) {
  if (mesh.vertices.empty()) return 0.0;
  // about the bounds centre: exact for closed meshes, a meaningful sign for open shells
  const PointBounds b = BoundsOf(mesh.vertices);
  return SignedVolumeAbout(mesh, 0.5 * (b.lo + b.hi));
}

double SignedVolumeAbout(const TriMesh& mesh, const Vec3& point) {
  // determinism: serial sum in triangle order
  double six_volume = 0.0;
  for (const auto& t : mesh.triangles) {
    const Vec3 a = mesh.vertices[t[0]] - point;
    const Vec3 b = mesh.vertices[t[1]] - point;
    const Vec3 c = mesh.vertices[t[2]] - point;
    six_volume += a.dot(b.cross(c));
  }
  return six_volume / 6.0;
}

Vec3 SurfaceCentroid(const TriMesh& mesh) {
  Vec3 weighted = Vec3::Zero();
  double area = 0.0;
  for (const auto& t : mesh.triangles) {
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const double twice = TriangleCross(a, b, c).norm();
    weighted += twice * (a + b + c);
    area += 3.0 * twice;
  }
  return area > 0.0 ? Vec3(weighted / area) : Vec3::Zero();
}

void FlipWinding(TriMesh* mesh) {
  for (auto& t : mesh->triangles) std::swap(t[1], t[2]);
}

int RemoveDegenerateTriangles(TriMesh* mesh) {
  // keep non-degenerate triangles in order; vertices are left as they are
  const std::size_t before = mesh->triangles.size();
  std::erase_if(mesh->triangles, [mesh](const std::array<int, 3>& t) { return IsDegenerate(*mesh, t); });
  return static_cast<int>(before - mesh->triangles.size());
}

}  // namespace dymesh

namespace dymesh {

int CylinderRows(double radius, double height, int segments) {
  // rows about as tall as a facet is wide (capped: memory is checked on the count it gives)
  const double facet = 2.0 * radius * std::sin(3.14159265358979323846 / segments);
  return static_cast<int>(std::clamp(std::round(height / facet), 1.0, 1e9));
}

TriMesh MakeCylinder(double radius, double height, int segments) {
  if (!(radius > 0.0) || !(height > 0.0) || !std::isfinite(radius) || !std::isfinite(height))
    throw std::invalid_argument("MakeCylinder: radius and height must be finite and > 0");
  if (segments < 3) throw std::invalid_argument("MakeCylinder: at least 3 segments");
  const int rows = CylinderRows(radius, height, segments);
  TriMesh mesh;
  for (int r = 0; r <= rows; ++r)
    for (int k = 0; k < segments; ++k) {
      const double angle = 2.0 * 3.14159265358979323846 * k / segments;
      mesh.vertices.emplace_back(radius * std::cos(angle), radius * std::sin(angle), -0.5 * height + height * r / rows);
    }
  auto id = [&](int r, int k) { return r * segments + (k % segments); };
  // side quads as two triangles, outward
  for (int r = 0; r < rows; ++r)
    for (int k = 0; k < segments; ++k) {
      mesh.triangles.push_back({id(r, k), id(r + 1, k), id(r, k + 1)});
      mesh.triangles.push_back({id(r, k + 1), id(r + 1, k), id(r + 1, k + 1)});
    }
  // caps: fans about centre vertices (bottom z = -h/2 faces -z, top faces +z)
  const int bottom = static_cast<int>(mesh.vertices.size());
  mesh.vertices.emplace_back(0.0, 0.0, -0.5 * height);
  mesh.vertices.emplace_back(0.0, 0.0, 0.5 * height);
  for (int k = 0; k < segments; ++k) {
    mesh.triangles.push_back({bottom, id(0, k), id(0, k + 1)});
    mesh.triangles.push_back({bottom + 1, id(rows, k + 1), id(rows, k)});
  }
  if (SignedVolume(mesh) < 0.0) FlipWinding(&mesh);
  return mesh;
}

}  // namespace dymesh

namespace dymesh {

int CountDuplicateFaces(const TriMesh& mesh, std::array<int, 2>* first) {
  // each triangle's sorted corners with its index; equal neighbours after sorting are repeats
  std::vector<std::pair<std::array<int, 3>, int>> keys;
  keys.reserve(mesh.triangles.size());
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    std::array<int, 3> k = mesh.triangles[t];
    std::sort(k.begin(), k.end());
    keys.push_back({k, t});
  }
  std::sort(keys.begin(), keys.end());
  int count = 0;
  std::array<int, 2> earliest{-1, -1};
  for (std::size_t i = 1; i < keys.size(); ++i) {
    if (keys[i].first != keys[i - 1].first) continue;
    ++count;
    // the repeat with the lowest index, and the first triangle of its group
    std::size_t g = i - 1;
    while (g > 0 && keys[g - 1].first == keys[i].first) --g;
    if (earliest[0] < 0 || keys[i].second < earliest[0]) earliest = {keys[i].second, keys[g].second};
  }
  if (first != nullptr) *first = earliest;
  return count;
}

}  // namespace dymesh
