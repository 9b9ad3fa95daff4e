#pragma once
// A host-driven engine (no Simulation): the barrier box (66 x 30 in front at x = 90 in at rest) and a
// rigid wall whose face is at x = 90.5 in; the test moves the box along its x each step. Shared by the
// reload and spring-back tests.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include "dymesh/accel/embree_locator.h"
#include "dymesh/core/contact_step.h"
#include "dymesh/io/body_models.h"
#include "test_scenarios.h"

namespace dymesh::testing {

inline constexpr double kWallFaceIn = 90.5;  // the wall's face [in]; the box's front is at 90 in at rest

// one way of setting up the same physical case: the options and arrangement a test varies
struct Arrangement {
  int passes = 2;
  SearchDirection search = SearchDirection::kVelocity;
  bool wall_first = false;  // body order
  double turn_deg = 0.0;    // both bodies' frame turned about the vertical
  int refine = 1;           // the box's grid segments multiplied (2: each face cell split 1:4)
};

struct NamedArrangement {
  const char* name;
  Arrangement arrangement;
};

// the arrangements a box-at-wall law is checked across: pass counts, search directions, body order,
// a turned frame and a finer box
inline std::vector<NamedArrangement> ArrangementVariants() {
  return {{"default", {}},
          {"1 pass", {1}},
          {"4 passes", {4}},
          {"specified", {2, SearchDirection::kSpecified}},
          {"local average normal", {2, SearchDirection::kLocalAverageNormal}},
          {"polygon normal", {2, SearchDirection::kPolyNormal}},
          {"wall listed first", {2, SearchDirection::kVelocity, true}},
          {"frame +30 deg", {2, SearchDirection::kVelocity, false, 30.0}},
          {"box mesh 1:4", {2, SearchDirection::kVelocity, false, 0.0, 2}}};
}

class BoxAtWall {
 public:
  // `s`: BarrierScenario with its other options set; the arrangement's pass count, search direction and
  // box grid, both frames turned about the vertical, the wall listed first if asked. The front face's
  // nodes are found and counted against its grid
  BoxAtWall(Scenario s, const Arrangement& a)
      : axes_(BodyToEarth(0.0, 0.0, a.turn_deg * M_PI / 180.0)), box_(a.wall_first ? 1 : 0) {
    s.contact.passes_per_step = a.passes;
    s.contact.search_direction = a.search;
    const std::array<int, 3> grid = {1, 22 * a.refine, 10 * a.refine};
    s.bodies[0].mesh.box_segments = grid;
    for (BodySpec& b : s.bodies) TurnAboutVertical(a.turn_deg * M_PI / 180.0, &b);
    if (a.wall_first) std::swap(s.bodies[0], s.bodies[1]);
    models_ = BuildBodyModels(s);
    engine_ = std::make_unique<ContactEngine>(
        models_, std::vector<RigidState>{s.bodies[0].initial, s.bodies[1].initial}, s.contact,
        accel::MakeEmbreeLocatorFactory(std::make_shared<const accel::EmbreeDevice>()));
    const auto& rest = models_[box_]->mesh.vertices;
    for (int v = 0; v < static_cast<int>(rest.size()); ++v)
      if (std::abs(rest[v].x() - 90.0 * units::kInch) < 1e-9) front_.push_back(v);
    EXPECT_EQ(front_.size(), static_cast<std::size_t>((grid[1] + 1) * (grid[2] + 1)));
  }

  // the box placed `penetration` [in] into the wall's face, moving at `speed` [in/s] along its x; one step
  StepResult Drive(double penetration, double speed, double dt) {
    RigidState r = engine_->state(box_).rigid;
    r.position = axes_ * Vec3((penetration + kWallFaceIn - 90.0) * units::kInch, 0, 0);
    r.velocity = axes_ * Vec3(speed * units::kInch, 0, 0);
    engine_->SetRigidState(box_, r);
    return engine_->Step(dt);
  }

  // the wall's centre moved to (x, y) [in] in the box's axes
  void PlaceWall(double x, double y) {
    RigidState w = engine_->state(1 - box_).rigid;
    w.position = axes_ * Vec3(x, y, 0) * units::kInch;
    engine_->SetRigidState(1 - box_, w);
  }

  double Deflection(int v) const { return engine_->state(box_).delta[v].norm() / units::kInch; }  // [in]
  double RestY(int v) const { return models_[box_]->mesh.vertices[v].y() / units::kInch; }       // [in]
  // the box's contact force along its -x [lbf]
  double ForceOnBox(const StepResult& r) const {
    return -(axes_.transpose() * r.loads[box_].force_earth).x() / units::kPoundForce;
  }
  const std::vector<int>& front() const { return front_; }

 private:
  Mat3 axes_;
  int box_;
  std::vector<std::shared_ptr<const BodyModel>> models_;
  std::unique_ptr<ContactEngine> engine_;
  std::vector<int> front_;
};

}  // namespace dymesh::testing
