#pragma once
#include <string>

#include "dymesh/core/mesh.h"

/// Reading a mesh file with assimp, guarded against what assimp does with bad files without a word.
namespace dymesh {

/// The triangles of every mesh in `path` (points and lines skipped), every node's transform applied,
/// vertices as assimp gives them (not welded). Refuses (InputError naming the file and `field`): a
/// file name whose extension assimp does not know (it would guess the format from the content, past
/// the text checks that run by extension: a PLY named .dat crashed it); a file assimp cannot read (its
/// message quoted printable and shortened: its STL reader quotes the rest of the file); a file that
/// references a FIFO, device or folder (an OBJ's material library, a glTF buffer: opening a FIFO
/// blocked the run), named; and a file whose faces or vertices assimp dropped with a warning only (a
/// glTF face with an index past the vertices), quoting the warning.
TriMesh ReadMeshWithAssimp(const std::string& path, const std::string& field);

}  // namespace dymesh
