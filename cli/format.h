#pragma once
#include <cstdio>
#include <string>

/// printf-style text for the dymesh command's messages.
namespace dymesh::cli {

/// `format` filled with `args` as printf would print it (at most 511 characters).
template <typename... Args>
std::string Format(const char* format, Args... args) {
  char text[512];
  std::snprintf(text, sizeof text, format, args...);
  return text;
}

}  // namespace dymesh::cli
