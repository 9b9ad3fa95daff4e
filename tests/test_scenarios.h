#pragma once
// Scenarios built in code for the validation tests (US inputs converted to SI here).
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "dymesh/core/scenario.h"
#include "dymesh/core/units.h"

namespace dymesh::testing {

namespace u = dymesh::units;

// a box-fronted deformable body: length x width x height [in], grid segments, weight [lb],
// 2-D stiffness A [lb/in], B [lb/in^2] on every surface with conversion height H [in]
inline BodySpec BoxVehicle(const std::string& name, double length, double width, double height,
                           std::array<int, 3> segments, double weight_lb, double a, double b, double h,
                           double restitution) {
  BodySpec body;
  body.name = name;
  body.mesh.box = true;
  body.mesh.box_size = Vec3(length, width, height) * u::kInch;
  body.mesh.box_segments = segments;
  body.mass = weight_lb * u::kPoundMass;
  const Stiffness k = StiffnessFrom2D(a * u::PoundPerInchPow(1), b * u::PoundPerInchPow(2), h * u::kInch);
  body.stiffness.fill(k);
  body.restitution = restitution;
  body.motion = MotionModel::kPlanar;
  return body;
}

// the earth frame turned by `angle` [rad] about the vertical: the body's pose and velocity seen from it
// (a frame change: the physical scene is the same)
inline void TurnAboutVertical(double angle, BodySpec* body) {
  const Mat3 turn = BodyToEarth(0.0, 0.0, angle);
  body->initial.position = turn * body->initial.position;
  body->initial.velocity = turn * body->initial.velocity;
  body->initial.yaw += angle;
}

// a rigid fixed wall whose face (normal -x) is at x = face_x [in]
inline BodySpec RigidWall(double face_x_in) {
  BodySpec wall;
  wall.name = "wall";
  wall.mesh.box = true;
  wall.mesh.box_size = Vec3(40, 400, 100) * u::kInch;
  wall.mesh.box_segments = {1, 4, 2};
  wall.rigid = true;
  wall.motion = MotionModel::kFixed;
  wall.initial.position = Vec3(face_x_in + 20.0, 0, 0) * u::kInch;
  return wall;
}

// a named change of a scenario that must not change its physics
using ScenarioVariant = std::pair<std::string, std::function<void(Scenario*)>>;

// the discretisation and frame variants every contact law is tested across: half the step, the
// other search directions than the default, the stop-after-one rule, 3 passes, the frame turned 30°
// (body order and mesh refinement depend on the scenario: each test adds its own)
inline std::vector<ScenarioVariant> ContactVariants() {
  return {
      {"dt/2", [](Scenario* s) { s->time_step /= 2.0; }},
      {"local average normal", [](Scenario* s) { s->contact.search_direction = SearchDirection::kLocalAverageNormal; }},
      {"polygon normal", [](Scenario* s) { s->contact.search_direction = SearchDirection::kPolyNormal; }},
      {"stop after one", [](Scenario* s) { s->contact.stop_rule = StopRule::kAfterOne; }},
      {"3 passes", [](Scenario* s) { s->contact.passes_per_step = 3; }},
      {"frame +30 deg", [](Scenario* s) {
         for (BodySpec& b : s->bodies) TurnAboutVertical(30.0 * u::kDegree, &b);
       }},
  };
}

// ContactVariants plus the first body's mesh 1:4 (one more subdivision) and the bodies listed the other
// way round, for a scenario whose first body is placed at contact with its second
inline std::vector<ScenarioVariant> ContactVariantsWithMeshAndOrder(const std::string& mesh_label,
                                                                    const std::string& order_label) {
  std::vector<ScenarioVariant> variants = ContactVariants();
  variants.push_back({mesh_label, [](Scenario* s) { s->bodies[0].mesh.subdivisions += 1; }});
  variants.push_back({order_label, [](Scenario* s) {
                        std::swap(s->bodies[0], s->bodies[1]);
                        s->bodies[1].place_at_contact->with = 0;  // the other body, now listed first
                      }});
  return variants;
}

// an empty scenario in US units: its name in error messages, time step [s] and duration [s]
inline Scenario UsScenario(const std::string& file, double time_step, double duration) {
  Scenario s;
  s.file = file;
  s.units = UnitSystem::kUS;
  s.time_step = time_step;
  s.duration = duration;
  return s;
}

// spec §4 test case: 66 in wide, 30 in high, 3000 lb, A = 300 lb/in, B = 100 lb/in^2, H = 30 in,
// at `speed_mph` into a rigid wall 0.5 in ahead of its front face
inline Scenario BarrierScenario(double speed_mph, double restitution, double time_step) {
  Scenario s = UsScenario("(barrier test)", time_step, 0.4);
  s.contact.search_direction = SearchDirection::kVelocity;
  BodySpec car = BoxVehicle("box", 180, 66, 30, {1, 22, 10}, 3000, 300, 100, 30, restitution);
  car.initial.velocity = Vec3(speed_mph * u::kMph, 0, 0);
  s.bodies = {car, RigidWall(90.5)};
  return s;
}

}  // namespace dymesh::testing
