#pragma once
#include <string>
#include <string_view>

/// JSON paths of fields as input messages name them ("bodies[0].initial.speed").
namespace dymesh::json_path {

/// path.key (key alone at the root)
inline std::string Join(const std::string& path, std::string_view key) {
  return path.empty() ? std::string(key) : path + "." + std::string(key);
}

/// path[index]
inline std::string At(const std::string& path, std::size_t index) { return path + "[" + std::to_string(index) + "]"; }

/// the path, or "(root)" for the whole document
inline std::string FieldName(const std::string& path) { return path.empty() ? "(root)" : path; }

}  // namespace dymesh::json_path
