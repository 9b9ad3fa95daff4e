// Scenario JSON: unit conversion of a good scenario, and one refusal per kind of bad input, each
// naming the file and the field.
#include "dymesh/io/body_models.h"
#include "dymesh/io/scenario_json.h"
#include "dymesh/core/scenario.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "dymesh/io/mesh_import.h"
#include "dymesh/core/simulation.h"
#include "dymesh/core/units.h"

namespace dymesh {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

void WriteText(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out << text;
}

// a good US scenario: a file-mesh car, a car from an SI vehicle file, a rigid wall
constexpr const char* kGoodScenario = R"({
  "name": "conversion test",
  "units": "US",
  "time": {"step": 0.001, "duration": 0.2, "stop_at_separation": false},
  "contact": {"passes_per_step": 3, "search_direction": "specified", "specified_direction": [0, 3, 4],
              "stop_rule": "best_of_two", "version": 4, "null_band": 0.25, "toofar_maximum": 8,
              "pushback_reduction": 0.25, "friction_null_band": 2, "rebound_law": "literal",
              "calc_nabor_interval": 7, "turn_within_step": false, "contact_normal": "crushed"},
  "bodies": [
    {"name": "car",
     "mesh": {"file": "meshes/car.obj", "unit": "mm", "scale": 2, "axes": ["x", "z", "-y"], "subdivisions": 1},
     "weight": 3000, "cg": [10, 0, -20], "inertia": [3800, 20000, 22000],
     "restitution": 0.1, "friction": 0.5,
     "stiffness": {"default": {"A": 200, "B": 75},
                   "front": {"A": 350, "B": 125, "conversion_height": 25, "sat_crush": 20, "Kv": 50},
                   "back": {"A3": 10, "B3": 4, "C3": -0.5, "D3": 0.01, "max_crush": 30}},
     "initial": {"position": [100, -50, -20], "heading": 90, "speed": 30, "yaw_rate": 10}},
    {"name": "sedan", "vehicle": "vehicles/sedan.json", "restitution": 0.2,
     "initial": {"position": [0, 0, 0], "velocity": [10, 0, 0]}},
    {"name": "wall", "mesh": {"box": {"length": 40, "width": 400, "height": 100, "segments": [1, 4, 2]}},
     "rigid": true, "motion": "fixed", "initial": {"position": [300, 0, -50]}}
  ]
})";

// a vehicle file in SI units (its mesh path is relative to the vehicle file)
constexpr const char* kSedanVehicle = R"({
  "units": "SI",
  "mesh": {"file": "../meshes/car.obj", "unit": "mm"},
  "mass": 1500, "cg": [0.1, 0, -0.5], "restitution": 0.3, "friction": 0.4, "motion": "free",
  "stiffness": {"default": {"A": 50000, "B": 700000}}
})";

// a folder with the scenario's mesh and vehicle files, removed afterwards
class ScenarioFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("dymesh_scenario_test_" + std::string(info->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "meshes");
    WriteObj(MakeBox(4000.0, 1000.0, 1600.0, 4, 1, 2), (dir_ / "meshes" / "car.obj").string(), "y-up box, mm");
    WriteText(dir_ / "vehicles" / "sedan.json", kSedanVehicle);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  std::string ScenarioPath() const { return (dir_ / "scenario.json").string(); }
  std::string Abs(const std::string& relative) const { return (dir_ / relative).lexically_normal().string(); }
  static Json Good() { return Json::parse(kGoodScenario); }

  // parses `text` expecting a refusal that names `file` and `field`; returns the message
  std::string ExpectRefused(const std::string& text, const std::string& file, const std::string& field) const {
    try {
      ParseScenario(text, ScenarioPath());
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), file) << e.what();
      EXPECT_EQ(e.field(), field) << e.what();
      return e.what();
    }
    ADD_FAILURE() << "accepted, expected a refusal at " << field;
    return {};
  }
  std::string ExpectRefused(const Json& j, const std::string& field) const {
    return ExpectRefused(j.dump(), ScenarioPath(), field);
  }

  fs::path dir_;
};

TEST_F(ScenarioFiles, GoodUsScenarioConverts) {
  const Scenario s = ParseScenario(kGoodScenario, ScenarioPath());
  EXPECT_EQ(s.name, "conversion test");
  EXPECT_EQ(s.units, UnitSystem::kUS);
  EXPECT_EQ(s.time_step, 0.001);
  EXPECT_EQ(s.duration, 0.2);
  EXPECT_FALSE(s.stop_at_separation);
  ASSERT_EQ(s.bodies.size(), 3u);

  // contact options: lengths in inches, speed in mph, the rest as given or default
  const ContactOptions& c = s.contact;
  EXPECT_EQ(c.passes_per_step, 3);
  EXPECT_EQ(c.search_direction, SearchDirection::kSpecified);
  EXPECT_NEAR((c.specified_direction - Vec3(0, 0.6, 0.8)).norm(), 0.0, 1e-15);
  // the same direction written at extreme scales (its length overflowed, or underflowed to 0, before)
  for (const double scale : {1e200, 1e-200}) {
    Json j = Json::parse(kGoodScenario);
    j["contact"]["specified_direction"] = Json::array({0.0, 3.0 * scale, 4.0 * scale});
    EXPECT_NEAR((ParseScenario(j.dump(), ScenarioPath()).contact.specified_direction - Vec3(0, 0.6, 0.8)).norm(), 0.0,
                1e-15) << scale;
  }
  EXPECT_EQ(c.stop_rule, StopRule::kBestOfTwo);
  EXPECT_EQ(c.version, 4);
  EXPECT_DOUBLE_EQ(c.null_band, 0.00635);            // 0.25 in
  EXPECT_DOUBLE_EQ(c.toofar_maximum, 0.2032);        // 8 in
  EXPECT_DOUBLE_EQ(c.toofar_margin, 0.0254);         // default 1 in
  EXPECT_EQ(c.pushback_reduction, 0.25);
  EXPECT_DOUBLE_EQ(c.friction_null_band, 0.89408);   // 2 mph
  EXPECT_EQ(c.rebound_law, ReboundLaw::kLiteral);
  EXPECT_EQ(c.calc_nabor_interval, 7);
  EXPECT_FALSE(c.turn_within_step);  // the default is true: the key was read
  EXPECT_EQ(c.contact_normal, ContactNormal::kCrushed);  // the default is conforming

  // body 0: mesh source, mass properties
  const BodySpec& car = s.bodies[0];
  EXPECT_EQ(car.name, "car");
  EXPECT_EQ(car.mesh.file, Abs("meshes/car.obj"));
  EXPECT_FALSE(car.mesh.box);
  EXPECT_DOUBLE_EQ(car.mesh.scale, 0.002);           // mm times 2
  EXPECT_EQ(car.mesh.axes, (std::array<std::string, 3>{"x", "z", "-y"}));
  EXPECT_FALSE(car.mesh.fit_length.has_value());
  Json fit = Good();
  fit["bodies"][0]["mesh"] = {{"file", "meshes/car.obj"}, {"fit_length", 180}};
  EXPECT_DOUBLE_EQ(*ParseScenario(fit.dump(), ScenarioPath()).bodies[0].mesh.fit_length, 4.572);  // 180 in
  EXPECT_EQ(car.mesh.subdivisions, 1);
  EXPECT_DOUBLE_EQ(car.mass, 1360.77711);            // 3000 lb
  ASSERT_TRUE(car.cg.has_value());
  EXPECT_NEAR((*car.cg - Vec3(0.254, 0.0, -0.508)).norm(), 0.0, 1e-15);
  ASSERT_TRUE(car.inertia_diagonal.has_value());
  EXPECT_NEAR(car.inertia_diagonal->x(), 429.34235030, 1e-6);   // 3800 lb in s^2
  EXPECT_NEAR(car.inertia_diagonal->y(), 2259.69658055, 1e-6);  // 20000 lb in s^2
  EXPECT_EQ(car.restitution, 0.1);
  EXPECT_EQ(car.friction, 0.5);
  EXPECT_FALSE(car.rigid);
  EXPECT_EQ(car.motion, MotionModel::kPlanar);

  // stiffness: 2-D over the conversion height (default 30 in), 3-D per area
  const auto& k = car.stiffness;
  const Stiffness& left = k[static_cast<int>(BodySurface::kLeft)];
  EXPECT_NEAR(left.A, 45965.0486211, 1e-6);          // 200 lb/in over 30 in
  EXPECT_NEAR(left.B, 678617.843816, 1e-5);          // 75 lb/in^2 over 30 in
  const Stiffness& front = k[static_cast<int>(BodySurface::kFront)];
  EXPECT_NEAR(front.A, 96526.6021044, 1e-6);         // 350 lb/in over 25 in = 14 psi
  EXPECT_NEAR(front.B, 1357235.68763, 1e-4);         // 125 lb/in^2 over 25 in = 5 lb/in^3
  EXPECT_DOUBLE_EQ(front.sat_crush, 0.508);          // 20 in
  EXPECT_NEAR(front.unload_slope, 13572356.8763, 1e-3);  // Kv 50 lb/in^3
  const Stiffness& back = k[static_cast<int>(BodySurface::kBack)];
  EXPECT_NEAR(back.A, 68947.5729317, 1e-6);          // 10 lb/in^2
  EXPECT_NEAR(back.B, 1085788.55011, 1e-4);          // 4 lb/in^3
  EXPECT_NEAR(back.C, -5343447.5891, 1e-3);          // -0.5 lb/in^4
  EXPECT_NEAR(back.D, 4207439.04654, 1e-3);          // 0.01 lb/in^5
  EXPECT_DOUBLE_EQ(back.max_crush, 0.762);           // 30 in
  EXPECT_EQ(k[static_cast<int>(BodySurface::kTop)].A, left.A);

  // initial state: inches, degrees, mph along the heading, yaw rate as body r
  const RigidState& r = car.initial;
  EXPECT_NEAR((r.position - Vec3(2.54, -1.27, -0.508)).norm(), 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(r.yaw, 0.5 * 3.14159265358979323846);
  EXPECT_NEAR((r.velocity - Vec3(0.0, 13.4112, 0.0)).norm(), 0.0, 1e-12);  // 30 mph east
  EXPECT_NEAR((r.omega - Vec3(0.0, 0.0, 0.174532925199)).norm(), 0.0, 1e-12);

  // body 1: vehicle file in SI, then the scenario's own fields
  const BodySpec& sedan = s.bodies[1];
  EXPECT_EQ(sedan.mesh.file, Abs("meshes/car.obj"));
  EXPECT_DOUBLE_EQ(sedan.mesh.scale, 0.001);
  EXPECT_EQ(sedan.mass, 1500.0);
  EXPECT_NEAR((*sedan.cg - Vec3(0.1, 0.0, -0.5)).norm(), 0.0, 1e-15);
  EXPECT_EQ(sedan.restitution, 0.2);                 // overridden by the scenario
  EXPECT_EQ(sedan.friction, 0.4);
  EXPECT_EQ(sedan.motion, MotionModel::kFree6Dof);
  EXPECT_NEAR(sedan.stiffness[0].A, 65616.7979003, 1e-6);  // 50000 N/m over 0.762 m
  EXPECT_DOUBLE_EQ(sedan.initial.velocity.x(), 4.4704);    // 10 mph

  // body 2: a rigid fixed box in metres, no mass
  const BodySpec& wall = s.bodies[2];
  EXPECT_TRUE(wall.mesh.box);
  EXPECT_NEAR((wall.mesh.box_size - Vec3(1.016, 10.16, 2.54)).norm(), 0.0, 1e-15);
  EXPECT_EQ(wall.mesh.box_segments, (std::array<int, 3>{1, 4, 2}));
  EXPECT_TRUE(wall.rigid);
  EXPECT_EQ(wall.motion, MotionModel::kFixed);
  EXPECT_EQ(wall.mass, 0.0);
}

TEST_F(ScenarioFiles, GoodScenarioMeshesBuild) {
  const Scenario s = ParseScenario(kGoodScenario, ScenarioPath());
  // 4000 x 1000 x 1600 mm y-up box, doubled (scale 2), axes (x, z, -y)
  const MeshStats car = ComputeStats(BuildBodyMesh(s.bodies[0].mesh, s.file, "bodies[0].mesh"));
  EXPECT_NEAR(car.max.x() - car.min.x(), 8.0, 1e-9);
  EXPECT_NEAR(car.max.y() - car.min.y(), 3.2, 1e-9);
  EXPECT_NEAR(car.max.z() - car.min.z(), 2.0, 1e-9);
  // the same fitted to 180 in long
  MeshSource fitted = s.bodies[0].mesh;
  fitted.fit_length = 4.572;
  const MeshStats fit = ComputeStats(BuildBodyMesh(fitted, s.file, "bodies[0].mesh"));
  EXPECT_NEAR(fit.max.x() - fit.min.x(), 4.572, 1e-9);
  EXPECT_NEAR(fit.max.y() - fit.min.y(), 4.572 * 0.4, 1e-9);
  EXPECT_NEAR(fit.max.z() - fit.min.z(), 4.572 * 0.25, 1e-9);
  const MeshStats wall = ComputeStats(BuildBodyMesh(s.bodies[2].mesh, s.file, "bodies[2].mesh"));
  EXPECT_EQ(wall.open_edges, 0);
}

TEST_F(ScenarioFiles, LoadScenarioReadsTheFile) {
  WriteText(ScenarioPath(), kGoodScenario);
  const Scenario s = LoadScenario(ScenarioPath());
  EXPECT_EQ(s.file, ScenarioPath());
  EXPECT_EQ(s.bodies.size(), 3u);
}

TEST_F(ScenarioFiles, RefusesMissingScenarioFile) {
  const std::string path = Abs("none.json");
  try {
    LoadScenario(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.field(), "(file)");
  }
}

TEST_F(ScenarioFiles, RefusesMalformedJson) {
  const std::string message = ExpectRefused(R"({"units": "US",, "bodies": []})", ScenarioPath(), "(json)");
  EXPECT_NE(message.find("byte 16"), std::string::npos) << message;
}

TEST_F(ScenarioFiles, RefusesWrongType) {
  Json j = Good();
  j["bodies"][0].erase("weight");
  j["bodies"][0]["mass"] = "heavy";
  const std::string message = ExpectRefused(j, "bodies[0].mass");
  EXPECT_NE(message.find("expected a number > 0, got \"heavy\""), std::string::npos) << message;
  Json k = Good();
  k["bodies"][0]["initial"]["position"] = Json::array({1, 2});
  ExpectRefused(k, "bodies[0].initial.position");
}

TEST_F(ScenarioFiles, RefusesUnknownKeys) {
  Json j = Good();
  j["bodies"][0]["colour"] = "red";
  const std::string message = ExpectRefused(j, "bodies[0].colour");
  EXPECT_NE(message.find("allowed keys: name, vehicle, mesh"), std::string::npos) << message;
  Json k = Good();
  k["contact"]["passes"] = 2;
  ExpectRefused(k, "contact.passes");
  Json m = Good();
  m["bodies"][0]["stiffness"]["front"]["C"] = 1;
  ExpectRefused(m, "bodies[0].stiffness.front.C");
}

TEST_F(ScenarioFiles, RefusesMissingMeshFile) {
  Json j = Good();
  j["bodies"][0]["mesh"]["file"] = "meshes/none.obj";
  const std::string message = ExpectRefused(j, "bodies[0].mesh.file");
  EXPECT_NE(message.find("file not found: " + Abs("meshes/none.obj")), std::string::npos) << message;
}

TEST_F(ScenarioFiles, RefusesUnreadableMeshFile) {
  // the file exists, so parsing accepts it; loading the mesh refuses it
  WriteText(dir_ / "meshes" / "garbage.obj", "this is not a mesh\nf 7 8 9\n");
  Json j = Good();
  j["bodies"][0]["mesh"]["file"] = "meshes/garbage.obj";
  const Scenario s = ParseScenario(j.dump(), ScenarioPath());
  try {
    BuildBodyMesh(s.bodies[0].mesh, s.file, "bodies[0].mesh");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), Abs("meshes/garbage.obj"));
    EXPECT_EQ(e.field(), "bodies[0].mesh.file");
  }
}

TEST_F(ScenarioFiles, RefusesMeshFilesWithoutUsableTriangles) {
  // parsing accepts an existing file; building the body models (as run and check do) refuses it
  const std::pair<const char*, const char*> cases[] = {
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\n", "no face lines (\"f\")"},              // points only
      {"v 1e999 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "not finite as assimp reads them"},  // overflowing coordinate
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1e30 0 1\nf 1 2 3\nf 1 2 4\n", "extent 1e+30"},  // a stray vertex
  };
  for (const auto& [text, reason] : cases) {
    WriteText(dir_ / "meshes" / "bad.obj", text);
    Json j = Good();
    j["bodies"][0]["mesh"]["file"] = "meshes/bad.obj";
    const Scenario s = ParseScenario(j.dump(), ScenarioPath());
    try {
      BuildBodyModels(s);
      ADD_FAILURE() << "no error for " << reason;
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), Abs("meshes/bad.obj")) << e.what();
      EXPECT_EQ(e.field(), "bodies[0].mesh.file") << e.what();
      EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
    }
  }
}

TEST_F(ScenarioFiles, RefusesMalformedVehicleFile) {
  WriteText(dir_ / "vehicles" / "sedan.json", R"({"units": "SI", "mass": 1500,})");
  const std::string message = ExpectRefused(Good().dump(), Abs("vehicles/sedan.json"), "(json)");
  EXPECT_NE(message.find("malformed JSON"), std::string::npos) << message;
}

TEST_F(ScenarioFiles, RefusesBodyNamesUnusableAsFileNames) {
  // body names become output file names
  for (const char* name : {"../car", "a/b", "a\\b", "..", "tab\there"}) {
    Json j = Good();
    j["bodies"][0]["name"] = name;
    const std::string message = ExpectRefused(j, "bodies[0].name");
    EXPECT_NE(message.find("usable in file names"), std::string::npos) << message;
  }
  Json ok = Good();
  ok["bodies"][0]["name"] = "Peugeot 406 (1999)";
  EXPECT_NO_THROW(ParseScenario(ok.dump(), ScenarioPath()));
}

TEST_F(ScenarioFiles, RefusesNonFiniteNumber) {
  std::string text = Good().dump();
  const std::string weight = "\"weight\":3000";
  ASSERT_NE(text.find(weight), std::string::npos);
  text.replace(text.find(weight), weight.size(), "\"weight\":1e999");
  const std::string message = ExpectRefused(text, ScenarioPath(), "bodies[0].weight");
  EXPECT_NE(message.find("expected a finite number"), std::string::npos) << message;
}

TEST_F(ScenarioFiles, RefusesNegativeMass) {
  Json j = Good();
  j["bodies"][0].erase("weight");
  j["bodies"][0]["mass"] = -3;
  const std::string message = ExpectRefused(j, "bodies[0].mass");
  EXPECT_NE(message.find("expected a number > 0, got -3"), std::string::npos) << message;
}

TEST_F(ScenarioFiles, RefusesRestitutionAboveOne) {
  Json j = Good();
  j["bodies"][0]["restitution"] = 1.5;
  const std::string message = ExpectRefused(j, "bodies[0].restitution");
  EXPECT_NE(message.find("in [0, 1], got 1.5"), std::string::npos) << message;
}

TEST_F(ScenarioFiles, RefusesMissingRequiredFields) {
  Json j = Good();
  j["bodies"][1].erase("initial");
  ExpectRefused(j, "bodies[1].initial");
  Json k = Good();
  k.erase("units");
  ExpectRefused(k, "units");
  Json m = Good();
  m["bodies"][0]["initial"].erase("position");
  ExpectRefused(m, "bodies[0].initial.position");
  Json n = Good();
  n["bodies"][0].erase("weight");  // neither mass nor weight on a moving body
  ExpectRefused(n, "bodies[0].mass");
}

TEST_F(ScenarioFiles, RefusesMixedTwoAndThreeDStiffness) {
  Json j = Good();
  j["bodies"][0]["stiffness"]["front"]["A3"] = 5;
  const std::string message = ExpectRefused(j, "bodies[0].stiffness.front");
  EXPECT_NE(message.find("mixes"), std::string::npos) << message;
}

TEST_F(ScenarioFiles, RefusesDeformableBodyWithoutStiffness) {
  Json j = Good();
  j["bodies"][0]["stiffness"].erase("default");  // right, left, top, bottom now have none
  ExpectRefused(j, "bodies[0].stiffness");
}

TEST_F(ScenarioFiles, ErrorsInVehicleFileNameIt) {
  WriteText(dir_ / "vehicles" / "sedan.json",
            R"({"units": "SI", "mesh": {"file": "../meshes/car.obj"}, "mass": 1500,
                "stiffness": {"default": {"A": -1, "B": 700000}}})");
  const std::string message =
      ExpectRefused(Good().dump(), Abs("vehicles/sedan.json"), "stiffness.default.A");
  EXPECT_NE(message.find("expected a number >= 0, got -1"), std::string::npos) << message;
  // a missing vehicle file is the scenario's error
  Json j = Good();
  j["bodies"][1]["vehicle"] = "vehicles/none.json";
  ExpectRefused(j, "bodies[1].vehicle");
}

TEST_F(ScenarioFiles, RefusesOtherImpossibleInputs) {
  Json both = Good();
  both["bodies"][0]["mass"] = 1000;
  ExpectRefused(both, "bodies[0].weight");
  Json names = Good();
  names["bodies"][1]["name"] = "car";
  ExpectRefused(names, "bodies[1].name");
  Json one = Good();
  one["bodies"] = Json::array({one["bodies"][0]});
  ExpectRefused(one, "bodies");
  Json axes = Good();
  axes["bodies"][0]["mesh"]["axes"] = Json::array({"x", "y", "x"});
  ExpectRefused(axes, "bodies[0].mesh.axes");
  Json steps = Good();
  steps["time"]["step"] = 1e-9;
  ExpectRefused(steps, "time.duration");
  Json version = Good();
  version["contact"]["version"] = 5;
  ExpectRefused(version, "contact.version");
  Json zero = Good();
  zero["contact"]["specified_direction"] = Json::array({0, 0, 0});
  ExpectRefused(zero, "contact.specified_direction");
  // a duplicated key would silently keep the last value
  std::string text = Good().dump();
  const std::string weight = "\"weight\":3000";
  text.replace(text.find(weight), weight.size(), weight + "," + weight);
  ExpectRefused(text, ScenarioPath(), "bodies[0].weight");
}

// keys that would do nothing where they stand (fuzzing, 2026-11-25: each was accepted unsaid)
TEST_F(ScenarioFiles, RefusesKeysThatWouldHaveNoEffect) {
  Json direction = Good();
  direction["contact"]["search_direction"] = "velocity";
  EXPECT_NE(ExpectRefused(direction, "contact.specified_direction").find("acts only with \"search_direction\": \"specified\""),
            std::string::npos);
  // and the other way round: the specified search without its direction (it quietly used -x)
  Json no_direction = Good();
  no_direction["contact"].erase("specified_direction");
  EXPECT_NE(ExpectRefused(no_direction, "contact.specified_direction")
                .find("expected with \"search_direction\": \"specified\""),
            std::string::npos);
  for (const char* key : {"pushback_reduction", "pushback_reduce_limit"}) {
    Json version3 = Good();
    version3["contact"]["version"] = 3;
    version3["contact"].erase("pushback_reduction");
    version3["contact"][key] = 0.1;
    EXPECT_NE(ExpectRefused(version3, std::string("contact.") + key).find("acts only in version 4"), std::string::npos);
    version3["contact"].erase("version");  // version 3 by default
    ExpectRefused(version3, std::string("contact.") + key);
  }
  for (const char* key : {"unit", "scale"}) {
    Json fit = Good();
    fit["bodies"][0]["mesh"] = {{"file", "meshes/car.obj"}, {"fit_length", 180}, {key, key == std::string("unit") ? Json("mm") : Json(2)}};
    EXPECT_NE(ExpectRefused(fit, std::string("bodies[0].mesh.") + key).find("has no effect with \"fit_length\""),
              std::string::npos);
  }
  Json vertical = Good();
  vertical["bodies"][0]["initial"].erase("speed");
  vertical["bodies"][0]["initial"]["velocity"] = {30, 0, 5};
  EXPECT_NE(ExpectRefused(vertical, "bodies[0].initial.velocity[2]").find("holds its height: expected 0, got 5 mph"),
            std::string::npos);
  vertical["bodies"][0]["motion"] = "free";
  EXPECT_NO_THROW(ParseScenario(vertical.dump(), ScenarioPath()));
  Json rigid = Good();
  rigid["bodies"][2]["stiffness"] = {{"default", {{"A", 300}, {"B", 100}}}};
  EXPECT_NE(ExpectRefused(rigid, "bodies[2].stiffness").find("a rigid body takes no crush"), std::string::npos);
}

// a vehicle file's stiffness on a body the scenario makes rigid: the vehicle file serves other
// scenarios, so the body is kept, with a warning that its stiffness never acts
TEST_F(ScenarioFiles, WarnsOfAVehicleStiffnessOnABodyMadeRigid) {
  Json j = Good();
  j["bodies"][1]["rigid"] = true;
  const Scenario s = ParseScenario(j.dump(), ScenarioPath());
  ASSERT_TRUE(s.bodies[1].rigid);
  const auto unused = std::find_if(s.warnings.begin(), s.warnings.end(), [](const RunWarning& w) { return w.code == "unused_stiffness"; });
  ASSERT_NE(unused, s.warnings.end());
  EXPECT_EQ(unused->field, "bodies[1].stiffness");
  EXPECT_NE(unused->message.find("\"sedan\" is rigid and takes no crush"), std::string::npos) << unused->message;
  // the vehicle file itself rigid with a stiffness: refused there
  WriteText(dir_ / "vehicles" / "sedan.json", R"({"units": "SI", "mesh": {"file": "../meshes/car.obj"}, "mass": 1500,
    "rigid": true, "stiffness": {"default": {"A": 50000, "B": 700000}}})");
  ExpectRefused(Good().dump(), Abs("vehicles/sedan.json"), "stiffness");
}

// a specified direction that does not push a deformable body's nodes back against its approach to
// another body is warned: its nodes look past that body (the barrier box searching along its y ran
// 2.8 m into the wall with no force). The car drives +x at a fixed wall ahead: pushback -x (its frame,
// heading 0) serves; +x, or y, or z does not; a wall behind it (receding) is not judged
TEST_F(ScenarioFiles, WarnsOfASpecifiedDirectionThatDoesNotPushBackAgainstTheApproach) {
  const auto warned = [&](const Json& j) {
    const Scenario s = ParseScenario(j.dump(), ScenarioPath());
    return std::count_if(s.warnings.begin(), s.warnings.end(),
                         [](const RunWarning& w) { return w.code == "specified_direction_away"; });
  };
  Json j = Good();
  j["bodies"].erase(1);  // the car and the wall
  j["bodies"][0]["initial"] = {{"position", {0, 0, -20}}, {"heading", 0}, {"speed", 30}};
  for (const auto& [direction, expected] : std::vector<std::pair<Json, int>>{
           {{-1, 0, 0}, 0}, {{-1, 0.5, 0}, 0}, {{1, 0, 0}, 1}, {{0, 1, 0}, 1}, {{0, 0, 1}, 1}}) {
    j["contact"]["specified_direction"] = direction;
    EXPECT_EQ(warned(j), expected) << direction.dump();
  }
  // square to the approach in a turned frame (round-off either side of 90 deg): warned as in the plain one
  j["contact"]["specified_direction"] = {0, 1, 0};
  j["bodies"][0]["initial"] = {{"position", {0, 0, -20}}, {"heading", 30}, {"speed", 30}};
  const double turn = std::acos(-1.0) / 6;  // 30 deg
  j["bodies"][1]["initial"]["position"] = {300 * std::cos(turn), 300 * std::sin(turn), -50};
  EXPECT_EQ(warned(j), 1);
  j["contact"]["specified_direction"] = {1, 0, 0};
  j["bodies"][0]["initial"]["heading"] = 0;
  j["bodies"][1]["initial"]["position"] = {-300, 0, -50};  // the wall behind the car
  EXPECT_EQ(warned(j), 0);
}

// the specified search direction between two deformable bodies is warned: one body-frame direction
// serves both as slaves, and where they push back along different lines one sinks into the other (a
// sweep of options, 2026-11-28: the side demo 19 in past the struck car's crush, unmarked). The good
// scenario has two deformable cars; with one of them rigid, none
TEST_F(ScenarioFiles, WarnsOfTheSpecifiedDirectionBetweenDeformableBodies) {
  const auto warned = [](const Scenario& s) {
    return std::count_if(s.warnings.begin(), s.warnings.end(),
                         [](const RunWarning& w) { return w.code == "specified_direction_shared"; });
  };
  EXPECT_EQ(warned(ParseScenario(Good().dump(), ScenarioPath())), 1);
  Json one = Good();
  one["bodies"][0]["rigid"] = true;
  one["bodies"][0].erase("stiffness");
  EXPECT_EQ(warned(ParseScenario(one.dump(), ScenarioPath())), 0);
  Json velocity = Good();
  velocity["contact"]["search_direction"] = "velocity";
  velocity["contact"].erase("specified_direction");
  EXPECT_EQ(warned(ParseScenario(velocity.dump(), ScenarioPath())), 0);
}

TEST(RepositoryScenarios, AllParse) {
  // every scenario shipped in data/ loads, with its vehicles and meshes
  const fs::path root = fs::path(DYMESH_DATA_DIR) / "scenarios";
  int count = 0;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    Scenario s;
    ASSERT_NO_THROW(s = LoadScenario(entry.path().string()));
    EXPECT_GE(s.bodies.size(), 2u);
    ++count;
  }
  EXPECT_GE(count, 3);
}

TEST(RepositoryScenarios, BarrierFrontalValues) {
  const Scenario s = LoadScenario(std::string(DYMESH_DATA_DIR) + "/scenarios/barrier_frontal.json");
  ASSERT_EQ(s.bodies.size(), 2u);
  const BodySpec& car = s.bodies[0];
  EXPECT_DOUBLE_EQ(car.mass, 3000 * units::kPoundMass);
  EXPECT_DOUBLE_EQ(car.initial.velocity.x(), 30 * units::kMph);
  EXPECT_DOUBLE_EQ(car.restitution, 0.1);
  // the car's front is about 1 in from the barrier face at t = 0
  const MeshStats mesh = ComputeStats(BuildBodyMesh(car.mesh, s.file, "bodies[0].mesh"));
  const double front = car.initial.position.x() + mesh.max.x() - car.cg->x();
  const double face = s.bodies[1].initial.position.x() - 0.5 * s.bodies[1].mesh.box_size.x();
  EXPECT_NEAR((face - front) / units::kInch, 1.0, 0.05);
}

}  // namespace
}  // namespace dymesh
