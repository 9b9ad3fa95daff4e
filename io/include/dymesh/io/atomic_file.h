#pragma once
#include <cstdio>
#include <functional>
#include <string>

/// The one way dymesh writes a file: under a unique temporary name beside it, renamed into place,
/// so a reader never sees half a file under the real name and two writers never share a temporary.
namespace dymesh {

/// Writes `path` through `body` (given the open temporary file) and renames it into place. On any
/// failure the temporary is removed and std::runtime_error names the path and the system's reason.
void WriteAtomically(const std::string& path, const std::function<void(std::FILE*)>& body);

/// Writes `text` to `path` atomically.
void WriteFileAtomically(const std::string& path, const std::string& text);

/// Temporary names are ".NAME.XXXXXX.tmp" beside the target: this many characters longer than NAME.
inline constexpr int kTemporaryNameExtra = 12;

}  // namespace dymesh
