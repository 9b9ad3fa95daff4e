#pragma once
// Two box cars head-on at 30 mph each whose faces are single quads (nodes 66 in apart across the
// front), shared by the pass-through tests: in line they crush and part; offset laterally, each
// side's nodes miss the other's faces and the boxes go through each other (README, Known limits).
#include <nlohmann/json.hpp>

namespace dymesh::testing {

// the scenario, "b" `offset_in` [in] to the left of "a"'s line
inline nlohmann::json CoarseBoxesHeadOn(double offset_in) {
  nlohmann::json car = nlohmann::json::parse(R"({
    "mesh": {"box": {"length": 180, "width": 66, "height": 30, "segments": [1, 1, 1]}},
    "weight": 3000, "restitution": 0.1, "stiffness": {"default": {"A": 300, "B": 100}}})");
  nlohmann::json a = car, b = car;
  a["name"] = "a";
  a["initial"] = {{"position", {0, 0, 0}}, {"speed", 30}};
  b["name"] = "b";
  b["initial"] = {{"position", {181, offset_in, 0}}, {"heading", 180}, {"speed", 30}};
  return {{"name", "coarse boxes head-on"}, {"units", "US"},
          {"time", {{"step", 0.0005}, {"duration", 0.5}, {"stop_at_separation", true}}},
          {"bodies", {a, b}}};
}

}  // namespace dymesh::testing
