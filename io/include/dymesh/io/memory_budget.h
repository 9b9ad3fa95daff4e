#pragma once
#include <cstdint>
#include <string>

/// Whether a mesh of a given size fits this machine's memory, asked before it is built.
namespace dymesh {

/// Bytes a body needs per triangle through set-up and the run: mesh, adjacency, body state,
/// locator BVH and the set-up copies (welding, subdivision). The run alone measures 311-338 B per
/// triangle (bench/README.md); set-up holds about two more copies of the mesh at its peak.
inline constexpr double kBytesPerTriangle = 600.0;

/// Memory this process may still take: MemAvailable of /proc/meminfo, else the physical pages
/// available (sysconf); 0 when unknown.
std::uint64_t AvailableMemoryBytes();

/// Throws InputError naming `file` and `field` when `triangles` would need more memory than is
/// available, with the estimate and what is free.
void RefuseMeshBeyondMemory(double triangles, const std::string& file, const std::string& field);

}  // namespace dymesh
