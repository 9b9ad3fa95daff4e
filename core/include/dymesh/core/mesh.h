#pragma once
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "dymesh/core/geometry.h"

/// Triangle meshes: storage, welding, vertex->triangle adjacency, subdivision, box generator, checks.
namespace dymesh {

/// An indexed triangle mesh (counter-clockwise triangles seen from outside).
struct TriMesh {
  std::vector<Vec3> vertices;                 // [m] positions (n_vertices)
  std::vector<std::array<int, 3>> triangles;  // vertex indices (n_triangles)
};

/// CSR vertex -> triangle adjacency: triangles of vertex v are ids[offsets[v] .. offsets[v+1]).
struct VertexTriangles {
  std::vector<int> offsets;  // (n_vertices + 1)
  std::vector<int> ids;      // (3 n_triangles)
};

/// Counts that tell whether a mesh is usable and how it is shaped.
struct MeshStats {
  int vertices = 0;
  int triangles = 0;
  int degenerate_triangles = 0;  ///< zero-area triangles
  int open_edges = 0;            ///< edges used by one triangle
  int nonmanifold_edges = 0;     ///< edges used by more than two triangles
  Vec3 min{0, 0, 0}, max{0, 0, 0};
};

/// Merges vertices closer than `tolerance` (grid hashing), drops triangles that collapse; stable order.
TriMesh Weld(const TriMesh& mesh, double tolerance);

/// Builds the CSR vertex -> triangle adjacency.
VertexTriangles BuildVertexTriangles(const TriMesh& mesh);

/// 1-to-4 midpoint subdivision: same surface, four times the triangles, shared midpoints.
TriMesh Subdivide(const TriMesh& mesh);

/// A closed box centred at the origin, `length` x `width` x `height` along x, y, z, with
/// `nx`, `ny`, `nz` grid segments along each axis; welded, outward normals.
TriMesh MakeBox(double length, double width, double height, int nx, int ny, int nz);

/// Axis-aligned bounds of points (lo = +inf, hi = -inf for none).
struct PointBounds {
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
};
PointBounds BoundsOf(const std::vector<Vec3>& points);

/// The largest distance of the points from the origin (a body's about its CG) [m]; 0 for none.
double FarthestFromOrigin(const std::vector<Vec3>& points);

/// Vertex, triangle, edge and bounds statistics.
MeshStats ComputeStats(const TriMesh& mesh);

/// Median length of the mesh's distinct edges [mesh units]; 0 for a mesh without edges.
double MedianEdgeLength(const TriMesh& mesh);

/// Closed upright cylinder about the origin (axis z): `segments` facets around, side rows about
/// as tall as a facet is wide, caps as fans about a centre vertex; wound outward.
TriMesh MakeCylinder(double radius, double height, int segments);

/// Side rows of MakeCylinder: about as tall as a facet is wide.
int CylinderRows(double radius, double height, int segments);

/// Triangles that repeat an earlier triangle's three vertices (any order or winding); `first`, when
/// given, receives the first repeat and the triangle it repeats.
int CountDuplicateFaces(const TriMesh& mesh, std::array<int, 2>* first = nullptr);

/// Signed volume (positive when triangles wind outward on a closed mesh), about the bounds centre.
double SignedVolume(const TriMesh& mesh);

/// Signed volume of the cones from `point` to every triangle: a closed mesh's volume wherever the point
/// is; for an open one it depends on the point (none for a flat sheet about a point on its plane).
double SignedVolumeAbout(const TriMesh& mesh, const Vec3& point);

/// Area-weighted mean of the triangles' centres (the origin for a mesh of no area): on the plane of a
/// flat sheet, however it is turned.
Vec3 SurfaceCentroid(const TriMesh& mesh);

/// Reverses every triangle's winding (used when a closed mesh is wound inward).
void FlipWinding(TriMesh* mesh);

/// Winds every face outward: each patch of faces joined across edges two faces share is wound alike, the
/// way most of its faces are, then the whole mesh faces out by its signed volume, and a closed patch, or an
/// open one whose faces were split near evenly, by its own (about the mesh's bounds centre). A patch that
/// cannot be wound one way is left as it is. Returns how many faces were turned on their own.
int OrientOutward(TriMesh* mesh);

/// Removes zero-area triangles (returns how many).
int RemoveDegenerateTriangles(TriMesh* mesh);

}  // namespace dymesh
