// summary.json against its documented schema (docs/summary.schema.json), with a small validator
// for the part of JSON Schema (draft 2020-12) the schema uses; it refuses any other keyword, so
// the schema cannot silently grow beyond what is checked.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "dymesh/report/output_files.h"
#include "dymesh/io/body_models.h"
#include "dymesh/accel/embree_locator.h"
#include "dymesh/analysis/summary.h"
#include "test_scenarios.h"

namespace dymesh {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

// validates `value` against `schema` (resolving "#/$defs/..." in `root`), collecting errors with JSON paths
class SchemaValidator {
 public:
  explicit SchemaValidator(const Json& root) : root_(root) {}

  std::vector<std::string> Validate(const Json& value) {
    errors_.clear();
    Check(root_, value, "$");
    return errors_;
  }

 private:
  void Fail(const std::string& path, const std::string& what) { errors_.push_back(path + ": " + what); }

  static bool HasType(const Json& v, const std::string& type) {
    if (type == "object") return v.is_object();
    if (type == "array") return v.is_array();
    if (type == "string") return v.is_string();
    if (type == "boolean") return v.is_boolean();
    if (type == "null") return v.is_null();
    if (type == "integer") return v.is_number_integer() || v.is_number_unsigned();
    if (type == "number") return v.is_number();
    return false;
  }

  void Check(const Json& schema, const Json& v, const std::string& path) {
    static const std::set<std::string> kKnown = {"$schema", "title", "description", "$defs", "$ref", "type",
                                                 "enum", "required", "additionalProperties", "properties",
                                                 "items", "minItems", "maxItems", "minimum", "maximum"};
    for (const auto& item : schema.items())
      if (!kKnown.count(item.key())) Fail(path, "schema keyword not supported by this validator: " + item.key());
    // reference, then the keywords beside it
    if (schema.contains("$ref")) {
      const std::string ref = schema["$ref"];
      ASSERT_EQ(ref.rfind("#/$defs/", 0), 0u) << ref;
      Check(root_["$defs"][ref.substr(8)], v, path);
    }
    if (schema.contains("type") && !HasType(v, schema["type"])) {
      Fail(path, "expected " + schema["type"].get<std::string>() + ", got " + v.dump());
      return;
    }
    if (schema.contains("enum") && std::find(schema["enum"].begin(), schema["enum"].end(), v) == schema["enum"].end())
      Fail(path, "not one of " + schema["enum"].dump() + ": " + v.dump());
    if (v.is_number()) CheckRange(schema, v.get<double>(), path);
    if (v.is_object()) CheckObject(schema, v, path);
    if (v.is_array()) CheckArray(schema, v, path);
  }

  void CheckRange(const Json& schema, double x, const std::string& path) {
    if (schema.contains("minimum") && x < schema["minimum"].get<double>()) Fail(path, "below minimum: " + std::to_string(x));
    if (schema.contains("maximum") && x > schema["maximum"].get<double>()) Fail(path, "above maximum: " + std::to_string(x));
  }

  void CheckObject(const Json& schema, const Json& v, const std::string& path) {
    for (const auto& key : schema.value("required", Json::array()))
      if (!v.contains(key.get<std::string>())) Fail(path, "missing required key " + key.get<std::string>());
    const Json properties = schema.value("properties", Json::object());
    for (const auto& item : v.items()) {
      if (properties.contains(item.key()))
        Check(properties[item.key()], item.value(), path + "." + item.key());
      else if (!schema.value("additionalProperties", true))
        Fail(path, "key not in the schema: " + item.key());
    }
  }

  void CheckArray(const Json& schema, const Json& v, const std::string& path) {
    if (schema.contains("minItems") && v.size() < schema["minItems"].get<std::size_t>()) Fail(path, "too few items");
    if (schema.contains("maxItems") && v.size() > schema["maxItems"].get<std::size_t>()) Fail(path, "too many items");
    if (schema.contains("items"))
      for (std::size_t i = 0; i < v.size(); ++i) Check(schema["items"], v[i], path + "[" + std::to_string(i) + "]");
  }

  const Json& root_;
  std::vector<std::string> errors_;
};

Json LoadSchema() {
  std::ifstream in(fs::path(DYMESH_DATA_DIR) / ".." / "docs" / "summary.schema.json");
  EXPECT_TRUE(in) << "docs/summary.schema.json not found";
  return Json::parse(in);
}

// runs a scenario (up to `max_steps` steps, then stopped) and returns the summary.json it writes
Json RunAndReadSummary(const Scenario& scenario, int max_steps, const std::string& name) {
  auto device = std::make_shared<const accel::EmbreeDevice>();
  Simulation sim(scenario, BuildBodyModels(scenario), accel::MakeEmbreeLocatorFactory(device));
  sim.Run([&](double) { return sim.steps() < max_steps; });
  const fs::path dir = fs::temp_directory_path() / ("dymesh_schema_test_" + name);
  WriteOutputs(sim, Summarize(sim), dir.string());
  std::ifstream in(dir / "summary.json");
  Json j = Json::parse(in);
  fs::remove_all(dir);
  return j;
}

std::string Join(const std::vector<std::string>& errors) {
  std::string s;
  for (const std::string& e : errors) s += e + "\n";
  return s;
}

TEST(SummarySchema, EveryPropertyIsDocumented) {
  const Json schema = LoadSchema();
  // walk every "properties" block in the schema
  std::vector<std::pair<std::string, Json>> stack = {{"$", schema}};
  int documented = 0;
  while (!stack.empty()) {
    auto [path, node] = stack.back();
    stack.pop_back();
    if (!node.is_object()) continue;
    if (node.contains("properties"))
      for (const auto& item : node["properties"].items()) {
        EXPECT_TRUE(item.value().contains("description")) << path << "." << item.key() << " has no description";
        ++documented;
      }
    for (const auto& item : node.items()) stack.emplace_back(path + "." + item.key(), item.value());
  }
  EXPECT_GT(documented, 50);
}

TEST(SummarySchema, FinishedRunsInBothUnitSystemsValidate) {
  const Json schema = LoadSchema();
  SchemaValidator validator(schema);
  Scenario us = testing::BarrierScenario(30.0, 0.1, 0.0005);
  const Json a = RunAndReadSummary(us, 1 << 30, "us");
  EXPECT_EQ(Join(validator.Validate(a)), "");
  EXPECT_EQ(a["overall"]["status"], "complete");
  EXPECT_EQ(a["units"]["speed"], "mph");
  EXPECT_EQ(a["bodies"][0]["crush_profile"]["face"], "front");
  Scenario si = us;
  si.units = UnitSystem::kSI;
  si.duration = 0.02;
  const Json b = RunAndReadSummary(si, 1 << 30, "si");
  EXPECT_EQ(Join(validator.Validate(b)), "");
  EXPECT_EQ(b["units"]["energy"], "J");
}

TEST(SummarySchema, InterruptedAndContactlessRunsValidate) {
  const Json schema = LoadSchema();
  SchemaValidator validator(schema);
  Scenario s = testing::BarrierScenario(30.0, 0.1, 0.0005);
  // stopped after the first step, before any contact: no crush, contact times -1
  const Json j = RunAndReadSummary(s, 1, "stopped");
  EXPECT_EQ(Join(validator.Validate(j)), "");
  EXPECT_EQ(j["overall"]["status"], "interrupted");
  EXPECT_EQ(j["overall"]["contact_start_s"], -1.0);
  EXPECT_EQ(j["bodies"][0]["crush_profile"]["face"], "none");
}

TEST(SummarySchema, ValidatorCatchesViolations) {
  const Json schema = LoadSchema();
  SchemaValidator validator(schema);
  const Json good = RunAndReadSummary(testing::BarrierScenario(30.0, 0.1, 0.0005), 10, "violations");
  ASSERT_EQ(Join(validator.Validate(good)), "");
  auto errors_of = [&](const std::function<void(Json&)>& change) {
    Json j = good;
    change(j);
    return Join(validator.Validate(j));
  };
  EXPECT_NE(errors_of([](Json& j) { j["overall"].erase("steps"); }).find("$.overall: missing required key steps"), std::string::npos);
  EXPECT_NE(errors_of([](Json& j) { j["bodies"][0]["delta_v"] = "fast"; }).find("$.bodies[0].delta_v: expected number"), std::string::npos);
  EXPECT_NE(errors_of([](Json& j) { j["bodies"][1]["colour"] = 1; }).find("key not in the schema: colour"), std::string::npos);
  EXPECT_NE(errors_of([](Json& j) { j["units"]["speed"] = "kph"; }).find("$.units.speed: not one of"), std::string::npos);
  EXPECT_NE(errors_of([](Json& j) { j["bodies"][0]["pdof_clock"] = 13; }).find("above maximum"), std::string::npos);
  EXPECT_NE(errors_of([](Json& j) { j["overall"]["momentum_after"] = Json::array({1, 2}); }).find("too few items"), std::string::npos);
  EXPECT_NE(errors_of([](Json& j) { j["overall"]["energy_balance_error"] = nullptr; }).find("expected number"), std::string::npos);
}

}  // namespace
}  // namespace dymesh
