// The spec hash names what an ensemble's samples depend on: a folder's records are resumed only
// under the same hash, so every file the samples read must be in it (spec, base scenario, vehicle
// files, meshes). Before, a vehicle file edited between a kill and the resume mixed the two.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "dymesh/ensemble/spec.h"

namespace dymesh::ensemble {
namespace {

namespace fs = std::filesystem;

// writes `text` to dir/name
void Write(const fs::path& dir, const std::string& name, const std::string& text) { std::ofstream(dir / name) << text; }

// a base scenario whose first body comes from a vehicle file with an OBJ mesh (a unit-cube-like box)
fs::path WriteFiles(const std::string& vehicle_weight, const std::string& top_corner) {
  const fs::path dir = fs::path(::testing::TempDir()) / "spec_hash";
  fs::create_directories(dir);
  Write(dir, "box.obj",
        "v 0 0 0\nv 100 0 0\nv 100 60 0\nv 0 60 0\nv 0 0 30\nv 100 0 30\nv 100 60 30\nv 0 60 " + top_corner + "\n"
        "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n");
  Write(dir, "car.json", R"({"units": "US", "mesh": {"file": "box.obj", "unit": "in"}, "weight": )" + vehicle_weight +
                             R"(, "stiffness": {"default": {"A": 300, "B": 100}}})");
  Write(dir, "scenario.json", R"({"units": "US", "time": {"step": 0.0005, "duration": 0.2},
    "bodies": [{"name": "car", "vehicle": "car.json", "initial": {"position": [0, 0, 0], "speed": 30}},
               {"name": "wall", "mesh": {"box": {"length": 40, "width": 400, "height": 100}}, "rigid": true,
                "motion": "fixed", "initial": {"position": [130, 30, 15]}}]})");
  Write(dir, "spec.json", R"({"scenario": "scenario.json", "samples": 4, "seed": 1, "inputs": [
    {"name": "speed", "path": "bodies[0].initial.speed", "distribution": {"uniform": {"low": 25, "high": 35}}}]})");
  return dir / "spec.json";
}

TEST(SpecHash, CoversTheVehicleAndMeshFilesTheScenarioReads) {
  const std::uint64_t base = LoadSpec(WriteFiles("3000", "30").string()).hash;
  EXPECT_EQ(LoadSpec(WriteFiles("3000", "30").string()).hash, base);  // the same files, the same hash
  EXPECT_NE(LoadSpec(WriteFiles("6000", "30").string()).hash, base);  // the vehicle's weight edited
  EXPECT_NE(LoadSpec(WriteFiles("3000", "31").string()).hash, base);  // one mesh vertex moved
}

}  // namespace
}  // namespace dymesh::ensemble
