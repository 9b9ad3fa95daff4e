#pragma once
// A small, fast ensemble spec for the tests: the validation box into a rigid wall, speed and
// restitution uncertain.
#include <filesystem>
#include <fstream>
#include <string>

namespace dymesh::testing {

// writes the spec into `dir` and returns its path; `extra` adds inputs (JSON array items, with a comma first);
// `samples` is left out for the designs that count their own runs (grid, one_at_a_time, table)
inline std::string WriteBoxSpec(const std::filesystem::path& dir, int samples, const std::string& design = "latin_hypercube",
                                const std::string& extra = "") {
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "spec.json").string();
  const bool own_count = design == "grid" || design == "one_at_a_time" || design == "table";
  std::ofstream(path) << R"({
    "scenario": ")" << DYMESH_DATA_DIR << R"(/scenarios/validation/box_barrier_30mph.json",
    "design": ")" << design << R"(", )" << (own_count ? "" : "\"samples\": " + std::to_string(samples) + ", ") << R"("seed": 7,
    "inputs": [
      {"name": "speed", "path": "bodies[0].initial.speed", "distribution": {"uniform": {"low": 25, "high": 35}}},
      {"name": "restitution", "path": "bodies[0].restitution", "distribution": {"uniform": {"low": 0.0, "high": 0.2}},
       "bounds": [0, 1]})" << extra << R"(
    ],
    "thresholds": [{"output": "box.delta_v", "above": 33}]
  })";
  return path;
}

}  // namespace dymesh::testing
