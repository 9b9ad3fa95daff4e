#include "dymesh/io/memory_budget.h"

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "dymesh/core/scenario.h"

namespace dymesh {

std::uint64_t AvailableMemoryBytes() {
  // the kernel's estimate of what can be allocated without swapping
  std::ifstream meminfo("/proc/meminfo");
  std::string line;
  while (std::getline(meminfo, line)) {
    std::istringstream fields(line);
    std::string key;
    std::uint64_t kib = 0;
    if (fields >> key >> kib && key == "MemAvailable:") return kib * 1024;
  }
  const long pages = sysconf(_SC_AVPHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  return pages > 0 && page > 0 ? static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page) : 0;
}

void RefuseMeshBeyondMemory(double triangles, const std::string& file, const std::string& field) {
  const std::uint64_t available = AvailableMemoryBytes();
  const double needed = triangles * kBytesPerTriangle;
  if (available == 0 || needed <= static_cast<double>(available)) return;
  char text[320];
  std::snprintf(text, sizeof text,
                "the mesh would have %.3g triangles and need about %.1f GiB, more than the %.1f GiB of memory "
                "available: use fewer segments or subdivisions, or a coarser mesh",
                triangles, needed / (1u << 30), static_cast<double>(available) / (1u << 30));
  throw InputError(file, field, text);
}

}  // namespace dymesh
