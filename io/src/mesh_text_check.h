#pragma once
#include <string>

/// Reads a PLY or OFF file through once before assimp sees it: assimp aborts or crashes on counts its
/// data does not hold and on face indices past the vertices, and reserves what a header claims.
namespace dymesh {

/// Refuses (InputError naming the file, the field and the line) a PLY or OFF file whose header
/// counts its data cannot hold, or whose faces (ASCII) have fewer than three corners or a corner
/// outside the vertices. Other extensions are left alone.
void CheckPlyOrOff(const std::string& path, const std::string& field);

}  // namespace dymesh
