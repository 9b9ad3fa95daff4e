#pragma once
#include <string>
#include <vector>

#include "dymesh/core/mesh.h"
#include "dymesh/core/scenario.h"
#include "dymesh/io/rgb.h"

/// Mesh files in (assimp: OBJ, STL, PLY, glTF, ...) and out (OBJ, PLY), and a body's mesh from its source.
namespace dymesh {

/// Most 1-to-4 subdivisions a mesh source may ask for (each quadruples the triangles).
inline constexpr int kMaxSubdivisions = 6;

/// What an axes mapping must be, for messages.
inline constexpr const char* kAxesExpected =
    "expected a permutation of x, y, z, each optionally negated (e.g. [\"x\", \"z\", \"-y\"])";

/// Index of a signed axis name ("x", "-y", ...): 0, 1 or 2, or -1 when it is none of the six.
int SignedAxisIndex(const std::string& name);

/// Whether three signed axis names are a permutation of x, y, z (the one check of a mapping).
bool IsAxesPermutation(const std::array<std::string, 3>& axes);

/// Loads every triangle of a mesh file into one mesh (file units, file axes), welded.
/// Throws InputError(path, field, ...) for a missing, unreadable or empty file.
TriMesh LoadMeshFile(const std::string& path, const std::string& field);

/// The body-frame mesh of a body: load or generate, map axes, scale, subdivide, weld, drop
/// degenerate triangles, orient outward. `field` names the JSON path for messages.
TriMesh BuildBodyMesh(const MeshSource& source, const std::string& scenario_file, const std::string& field);

/// Writes a mesh as Wavefront OBJ, to a temporary name renamed into place.
void WriteObj(const TriMesh& mesh, const std::string& path, const std::string& comment);

/// Writes a mesh as ASCII PLY with a float property `crush` and an 8-bit colour (red, green, blue)
/// per vertex, to a temporary name renamed into place. `crush` and `colours` have one entry per vertex.
void WritePly(const TriMesh& mesh, const std::vector<double>& crush, const std::vector<Rgb>& colours,
              const std::string& path, const std::string& comment);

}  // namespace dymesh
