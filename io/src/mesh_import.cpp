#include "dymesh/io/mesh_import.h"

#include "dymesh/io/atomic_file.h"
#include "dymesh/io/memory_budget.h"
#include "dymesh/io/scenario_json.h"
#include "assimp_read.h"
#include "mesh_text_check.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>

namespace dymesh {
namespace {

// weld tolerance relative to the bounds diagonal (merges only coincident vertices)
constexpr double kRelativeWeldTolerance = 1e-9;

// largest share of a mesh's faces that may repeat another face
constexpr double kMaxDuplicateFaces = 0.10;

// one signed axis of an axes mapping: body coordinate = sign * mesh coordinate[index]
struct SignedAxis {
  int index = -1;
  double sign = 1.0;
};

// "x", "-y", ... to a signed axis (index -1 when not one of the six names)
SignedAxis ParseSignedAxis(const std::string& name) {
  SignedAxis axis;
  std::string letter = name;
  if (!letter.empty() && letter[0] == '-') {
    axis.sign = -1.0;
    letter = letter.substr(1);
  }
  if (letter == "x") axis.index = 0;
  if (letter == "y") axis.index = 1;
  if (letter == "z") axis.index = 2;
  return axis;
}

// bounds diagonal of a mesh (0 when empty)
double BoundsDiagonal(const TriMesh& mesh) {
  if (mesh.vertices.empty()) return 0.0;
  Vec3 lo = mesh.vertices.front(), hi = lo;
  for (const Vec3& p : mesh.vertices) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

// weld with the tolerance relative to the mesh size
TriMesh WeldRelative(const TriMesh& mesh) { return Weld(mesh, kRelativeWeldTolerance * BoundsDiagonal(mesh)); }

// the axes mapping as three signed axes; refuses anything that is not a signed permutation
std::array<SignedAxis, 3> AxesMapping(const MeshSource& source, const std::string& scenario_file,
                                      const std::string& field) {
  if (!IsAxesPermutation(source.axes))
    throw InputError(scenario_file, field + ".axes",
                     std::string(kAxesExpected) + ", got [\"" + source.axes[0] + "\", \"" + source.axes[1] + "\", \"" +
                         source.axes[2] + "\"]");
  std::array<SignedAxis, 3> axes;
  for (int i = 0; i < 3; ++i) {
    axes[i] = ParseSignedAxis(source.axes[i]);
  }
  return axes;
}

}  // namespace

int SignedAxisIndex(const std::string& name) { return ParseSignedAxis(name).index; }

bool IsAxesPermutation(const std::array<std::string, 3>& axes) {
  bool used[3] = {false, false, false};
  for (const std::string& a : axes) {
    const int index = SignedAxisIndex(a);
    if (index < 0 || used[index]) return false;
    used[index] = true;
  }
  return true;
}

TriMesh LoadMeshFile(const std::string& path, const std::string& field) {
  // the file must exist
  if (const std::string problem = NotARegularFile(path); !problem.empty()) throw InputError(path, field, problem);
  CheckMeshText(path, field);
  TriMesh mesh = ReadMeshWithAssimp(path, field);
  // refuse non-finite coordinates and empty results
  for (const Vec3& p : mesh.vertices)
    if (!p.allFinite())
      throw InputError(path, field, "mesh has vertex coordinates that are not finite as assimp reads them (in single "
                                    "precision: beyond 3.4e38 a coordinate is infinite)");
  if (mesh.triangles.empty()) throw InputError(path, field, "mesh file has no triangles");
  // merge the vertices shared between assimp meshes
  TriMesh welded = WeldRelative(mesh);
  if (welded.triangles.empty()) {
    // say what the merge distance was: one stray vertex far from the rest stretches it over the mesh
    char what[200];
    std::snprintf(what, sizeof what,
                  "mesh file has no non-degenerate triangles once vertices closer than %.0e of its extent are "
                  "merged (extent %.3g file units: a stray vertex far from the rest stretches it)",
                  kRelativeWeldTolerance, BoundsDiagonal(mesh));
    throw InputError(path, field, what);
  }
  return welded;
}

TriMesh BuildBodyMesh(const MeshSource& source, const std::string& scenario_file, const std::string& field) {
  // a generated box is already in body axes and metres
  TriMesh mesh;
  // memory first: a generated mesh is refused before it is built
  const double refine = std::pow(4.0, source.subdivisions);
  if (source.cylinder) {
    const int rows = CylinderRows(source.cylinder_radius, source.cylinder_height, source.cylinder_segments);
    RefuseMeshBeyondMemory(2.0 * source.cylinder_segments * (rows + 1.0) * refine, scenario_file, field + ".cylinder");
    mesh = MakeCylinder(source.cylinder_radius, source.cylinder_height, source.cylinder_segments);
  } else if (source.box) {
    const Vec3& s = source.box_size;
    if (!(s.minCoeff() > 0.0) || !s.allFinite())
      throw InputError(scenario_file, field + ".box", "box sizes must be finite and > 0");
    const auto& n = source.box_segments;
    if (n[0] < 1 || n[1] < 1 || n[2] < 1)
      throw InputError(scenario_file, field + ".box.segments", "box segments must be >= 1");
    const double nx = n[0], ny = n[1], nz = n[2];
    RefuseMeshBeyondMemory(4.0 * (nx * ny + ny * nz + nx * nz) * refine, scenario_file, field + ".box.segments");
    mesh = MakeBox(s.x(), s.y(), s.z(), n[0], n[1], n[2]);
  } else {
    // a file: load, map the axes (body i = sign * mesh axis), scale to metres
    const std::array<SignedAxis, 3> axes = AxesMapping(source, scenario_file, field);
    if (!(source.scale > 0.0) || !std::isfinite(source.scale))
      throw InputError(scenario_file, field + ".scale", "expected a finite number > 0");
    const TriMesh file_mesh = LoadMeshFile(source.file, field + ".file");
    RefuseMeshBeyondMemory(static_cast<double>(file_mesh.triangles.size()) * refine, scenario_file, field + ".subdivisions");
    mesh.triangles = file_mesh.triangles;
    mesh.vertices.reserve(file_mesh.vertices.size());
    for (const Vec3& p : file_mesh.vertices)
      mesh.vertices.emplace_back(axes[0].sign * p[axes[0].index] * source.scale,
                                 axes[1].sign * p[axes[1].index] * source.scale,
                                 axes[2].sign * p[axes[2].index] * source.scale);
  }
  // fit the body-x extent to the requested length (uniform scale)
  if (source.fit_length) {
    const double target = *source.fit_length;
    if (!(target > 0.0) || !std::isfinite(target))
      throw InputError(scenario_file, field + ".fit_length", "expected a finite length > 0");
    const MeshStats stats = ComputeStats(mesh);
    const double extent = stats.max.x() - stats.min.x();
    if (!(extent > 0.0)) throw InputError(scenario_file, field + ".fit_length", "mesh has no extent along body x");
    const double factor = target / extent;
    for (Vec3& p : mesh.vertices) p *= factor;
  }
  // refine
  if (source.subdivisions < 0 || source.subdivisions > kMaxSubdivisions)
    throw InputError(scenario_file, field + ".subdivisions", "expected an integer in 0.." + std::to_string(kMaxSubdivisions));
  for (int i = 0; i < source.subdivisions; ++i) mesh = Subdivide(mesh);
  // clean: drop degenerate triangles, merge coincident vertices
  RemoveDegenerateTriangles(&mesh);
  mesh = WeldRelative(mesh);
  if (mesh.triangles.empty()) throw InputError(scenario_file, field, "mesh has no usable triangles");
  // faces given twice (any winding) make inside and outside ambiguous: the few double-sided panels
  // of display meshes are tolerated (the stock car has 3 %; `dymesh check` notes them), a mesh
  // with more than kMaxDuplicateFaces of its faces repeated is refused
  std::array<int, 2> repeat{};
  if (const int duplicates = CountDuplicateFaces(mesh, &repeat); duplicates > kMaxDuplicateFaces * mesh.triangles.size())
    throw InputError(source.box || source.cylinder ? scenario_file : source.file, field,
                     std::to_string(duplicates) + " duplicated faces (triangles on the same three vertices as another, "
                     "e.g. triangle " + std::to_string(repeat[0]) + " repeats " + std::to_string(repeat[1]) +
                     " after merging coincident vertices): remove them in a mesh editor");
  // every face outward, the faces wound against their neighbours too
  OrientOutward(&mesh);
  return mesh;
}

namespace {

// each line of `comment` after `prefix` ("# " for OBJ, "comment " for PLY)
void WriteComment(std::FILE* f, const std::string& prefix, const std::string& comment) {
  std::fputs(prefix.c_str(), f);
  for (char c : comment) {
    if (c == '\n') {
      std::fputc('\n', f);
      std::fputs(prefix.c_str(), f);
    } else {
      std::fputc(c, f);
    }
  }
  std::fputc('\n', f);
}

}  // namespace

void WriteObj(const TriMesh& mesh, const std::string& path, const std::string& comment) {
  WriteAtomically(path, [&](std::FILE* f) {
    // comment lines, vertices and 1-based faces
    WriteComment(f, "# ", comment);
    for (const Vec3& p : mesh.vertices) std::fprintf(f, "v %.9g %.9g %.9g\n", p.x(), p.y(), p.z());
    for (const auto& t : mesh.triangles) std::fprintf(f, "f %d %d %d\n", t[0] + 1, t[1] + 1, t[2] + 1);
  });
}

void WritePly(const TriMesh& mesh, const std::vector<double>& crush, const std::vector<Rgb>& colours,
              const std::string& path, const std::string& comment) {
  if (crush.size() != mesh.vertices.size() || colours.size() != mesh.vertices.size())
    throw std::invalid_argument("WritePly: one crush value and one colour per vertex expected (" + path + ")");
  WriteAtomically(path, [&](std::FILE* f) {
    // header: vertex position, crush scalar and colour; faces as index lists
    std::fputs("ply\nformat ascii 1.0\n", f);
    WriteComment(f, "comment ", comment);
    std::fprintf(f, "element vertex %zu\n", mesh.vertices.size());
    std::fputs("property float x\nproperty float y\nproperty float z\nproperty float crush\n", f);
    std::fputs("property uchar red\nproperty uchar green\nproperty uchar blue\n", f);
    std::fprintf(f, "element face %zu\nproperty list uchar int vertex_indices\nend_header\n", mesh.triangles.size());
    // body
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
      const Vec3& p = mesh.vertices[v];
      std::fprintf(f, "%.9g %.9g %.9g %.9g %d %d %d\n", p.x(), p.y(), p.z(), crush[v], colours[v].r, colours[v].g,
                   colours[v].b);
    }
    for (const auto& t : mesh.triangles) std::fprintf(f, "3 %d %d %d\n", t[0], t[1], t[2]);
  });
}

}  // namespace dymesh
