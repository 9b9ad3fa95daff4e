#pragma once
// `dymesh bench`: the benchmark suite's figures for two meshes the user brings.
#include <array>
#include <string>

namespace dymesh::cli {

/// What `dymesh bench` was asked for.
struct BenchRequest {
  std::string master, slave;  ///< mesh files (any format assimp reads), in metres
  std::array<std::string, 3> axes{"x", "y", "z"};  ///< body x, y, z from these signed mesh axes
  int threads = 2;            ///< worker threads for the step timing
  bool json = false;          ///< print JSON instead of a table
  std::string ensemble;       ///< an ensemble spec: time its samples instead (RunEnsembleBench)
  int samples = 8;            ///< ensemble samples timed per thread setting
};

/// Times an ensemble spec's samples at 1 and N threads (meshes loaded once, untimed) and reports
/// samples per second, seconds per 1000 samples and the memory a concurrent sample holds.
int RunEnsembleBench(const BenchRequest& request);

/// Places the slave's +x end 0.1 m into the master's -y side and prints locate rates (engine,
/// raw Embree, neighbour box, CGAL), step time at 1 and N threads, and memory per triangle.
int RunBench(const BenchRequest& request);

}  // namespace dymesh::cli
