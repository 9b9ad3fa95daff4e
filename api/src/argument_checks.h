#pragma once
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

/// Argument checks of the C ABI: a refused argument is DM_ERROR_ARGUMENT and its message
/// dm_last_error's.
namespace dymesh::api {

struct ArgumentError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

inline void Require(bool ok, const std::string& what) {
  if (!ok) throw ArgumentError(what);
}

template <typename T>
void NotNull(const T* p, const std::string& name) {
  Require(p != nullptr, name + " is null");
}

inline bool Finite(const double* v, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}

}  // namespace dymesh::api
