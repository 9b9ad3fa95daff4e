#pragma once
#include <string>
#include <vector>

#include "dymesh/core/mesh.h"
#include "dymesh/core/scenario.h"
#include "dymesh/io/rgb.h"

/// Mesh files in (assimp: OBJ, STL, PLY, glTF, ...) and out (OBJ, PLY), and a body's mesh from its source.
namespace dymesh {

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
