#pragma once
#include <string>

/// Reads an OBJ, PLY or OFF file through once before assimp sees it: assimp reads a bad OBJ number's
/// prefix and drops short faces without a word, aborts or crashes on PLY/OFF counts its data does not
/// hold and on face indices past the vertices, and reserves what a header claims.
namespace dymesh {

/// Refuses (InputError naming the file, the field and the line) an OBJ line that is not a whole
/// vertex or face; a PLY or OFF file whose header counts its data cannot hold, whose faces (ASCII)
/// have fewer than three corners or a corner outside the vertices, or (ASCII) with data past its
/// counts or a record of other than its properties' values; and an ASCII STL facet of other than three
/// vertices. Other extensions are left alone (ReadMeshWithAssimp refuses those assimp does not know).
void CheckMeshText(const std::string& path, const std::string& field);

}  // namespace dymesh
