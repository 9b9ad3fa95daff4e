// A node that sprang back and is pressed again (spec §6 reloading, MAX_GROW_UNLOAD) keeps up with the
// surface at any time step: a host drives a deformable box into a rigid wall, backs it off and drives
// it in again past the first peak. Against a rigid wall the crush is the penetration (the wall takes
// none), so every front node's deflection is known at every step.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "dymesh/accel/embree_locator.h"
#include "dymesh/core/contact_step.h"
#include "dymesh/io/body_models.h"
#include "test_scenarios.h"

namespace dymesh {
namespace {

namespace u = dymesh::units;

constexpr double kWallFaceIn = 90.5;  // the box's front face is at x = 90 in at rest
constexpr double kSpeed = 600.0;      // [in/s] a car-to-car closing speed (34 mph)

// the host's plan: penetration [in] at time t [s] — in to 3 in, back to 1.8 in, in again to 4.5 in
double Penetration(double t) {
  const double start = -0.3, peak = 3.0, back = 1.8;
  const double t1 = (peak - start) / kSpeed, t2 = t1 + (peak - back) / kSpeed;
  if (t <= t1) return start + kSpeed * t;
  if (t <= t2) return peak - kSpeed * (t - t1);
  return back + kSpeed * (t - t2);
}

double PlanEnd() { return (3.0 + 0.3 + 1.2 + 2.7) / kSpeed; }

struct ReloadRun {
  double worst_lag_in = 0.0;    // largest |front node deflection - penetration| over the run
  double final_force_lbf = 0.0;
};

// the box is moved by the host along x to the planned penetration each step (its velocity the plan's)
ReloadRun DriveIntoWall(double dt, double max_grow_unload_in, int passes) {
  Scenario s = testing::BarrierScenario(0.0, 0.5, dt);
  s.contact.max_grow_unload = max_grow_unload_in * u::kInch;
  s.contact.passes_per_step = passes;
  const auto models = BuildBodyModels(s);
  ContactEngine engine(models, {s.bodies[0].initial, s.bodies[1].initial}, s.contact,
                       accel::MakeEmbreeLocatorFactory(std::make_shared<const accel::EmbreeDevice>()));
  // the front face's nodes
  std::vector<int> front;
  const auto& rest = models[0]->mesh.vertices;
  for (int v = 0; v < static_cast<int>(rest.size()); ++v)
    if (std::abs(rest[v].x() - 90.0 * u::kInch) < 1e-9) front.push_back(v);
  EXPECT_EQ(front.size(), 23u * 11u);  // the 22 x 10 grid of the 66 x 30 in face
  ReloadRun out;
  const int steps = static_cast<int>(std::lround(PlanEnd() / dt));
  for (int k = 1; k <= steps; ++k) {
    RigidState r = engine.state(0).rigid;
    const double p = Penetration(k * dt);
    r.position.x() = (p + kWallFaceIn - 90.0) * u::kInch;
    r.velocity.x() = (p - Penetration((k - 1) * dt)) / dt * u::kInch;
    engine.SetRigidState(0, r);
    const StepResult result = engine.Step(dt);
    for (int v : front) {
      const double lag = engine.state(0).delta[v].norm() / u::kInch - std::max(p, 0.0);
      out.worst_lag_in = std::max(out.worst_lag_in, std::abs(lag));
    }
    out.final_force_lbf = -result.loads[0].force_earth.x() / u::kPoundForce;
  }
  return out;
}

TEST(Reload, FrontNodesFollowTheWallAtAnyStep) {
  // closed form at the end (4.5 in, past the 3 in peak: on the loading curve): the face's 66 x 30 in
  // times A/H + B/H (p - d0) with A = 300 lb/in, B = 100 lb/in^2, H = 30 in, d0 = 0.5 in
  const double expected = 66.0 * 30.0 * (300.0 / 30.0 + 100.0 / 30.0 * (4.5 - 0.5));
  // 1 ms steps close 0.6 in each: more than the 0.25 in allowance, so the reload relies on the
  // approach term; 0.25 ms close 0.15 in. Every pass meets the wall (a rigid master), so the
  // spring-back while backing off must not repeat per pass
  for (double dt : {0.001, 0.0005, 0.00025}) {
    for (double allowance : {0.25, 0.05}) {
      for (int passes : {1, 2, 4}) {
        const ReloadRun run = DriveIntoWall(dt, allowance, passes);
        std::printf("[measured] reload dt %.2f ms, allowance %.2f in, %d passes: worst lag %.2e in, end force %.1f lbf (closed form %.1f)\n",
                    dt * 1e3, allowance, passes, run.worst_lag_in, run.final_force_lbf, expected);
        // the crush is the penetration to round-off (1e-9 in: metres converted, many steps summed)
        EXPECT_LT(run.worst_lag_in, 1e-9) << "dt " << dt << " allowance " << allowance << " passes " << passes;
        // the face's tributary areas sum to its area; the pressure is the loading law's at 4.5 in
        EXPECT_NEAR(run.final_force_lbf, expected, 1e-6 * expected) << "dt " << dt << " passes " << passes;
      }
    }
  }
}

}  // namespace
}  // namespace dymesh
