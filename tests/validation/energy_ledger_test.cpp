// The energy ledger (LS-DYNA-style contact energy) and the conservation laws on the demos, the
// oblique and offset impacts, and at smaller time steps.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "dymesh/io/scenario_json.h"
#include "dymesh/io/body_models.h"
#include "dymesh/accel/embree_locator.h"
#include "dymesh/analysis/summary.h"
#include "dymesh/core/simulation.h"
#include "test_scenarios.h"

namespace dymesh {
namespace {

Scenario Demo(const std::string& name) { return LoadScenario(std::string(DYMESH_DATA_DIR) + "/scenarios/" + name); }

// angular momentum about the earth origin's vertical: sum of m (r x v)_z + Izz r of the moving bodies
double AngularMomentumZ(const Simulation& sim, const Sample& sample) {
  double l = 0.0;
  for (int i = 0; i < sim.engine().body_count(); ++i) {
    if (sim.scenario().bodies[i].motion == MotionModel::kFixed) continue;
    const BodyModel& m = sim.engine().model(i);
    const RigidState& s = sample.bodies[i].rigid;
    l += m.mass * s.position.cross(s.velocity).z() + m.inertia(2, 2) * s.omega.z();
  }
  return l;
}

void ExpectLedgerBalances(const Scenario& scenario, const std::string& label) {
  auto device = std::make_shared<const accel::EmbreeDevice>();
  Simulation sim(scenario, BuildBodyModels(scenario), accel::MakeEmbreeLocatorFactory(device));
  sim.Run();
  const Summary s = Summarize(sim);
  const double lost = s.kinetic_before - s.kinetic_after;
  ASSERT_GT(lost, 0.05 * s.kinetic_before) << label << ": a real collision";
  // the bar: kinetic energy lost = crush work + friction work within 2 %; the ledger takes
  // the work of the applied loads at the mean velocities of each step, exact for the planar host
  EXPECT_NEAR(s.crush_energy + s.friction_energy, lost, 0.02 * lost) << label;
  // equal and opposite loads at the same points: momentum and angular momentum to round-off
  const double p_scale = std::max(s.momentum_before.norm(), s.momentum_after.norm());
  EXPECT_LT((s.momentum_after - s.momentum_before).norm(), 1e-9 * p_scale) << label;
  const double l0 = AngularMomentumZ(sim, sim.history().front()), l1 = AngularMomentumZ(sim, sim.history().back());
  const double l_scale = p_scale * 5.0;  // [kg m^2/s] momentum times a lever of the bodies' size
  EXPECT_LT(std::abs(l1 - l0), 1e-9 * l_scale) << label;
  std::printf("[measured] %s: KE lost %.1f J, crush %.1f J, friction %.1f J, balance %.4f %%, node law %.1f J "
              "(discontinuity %.1f %% of the crush work), angular momentum drift %.2e\n",
              label.c_str(), lost, s.crush_energy, s.friction_energy, 100 * s.energy_balance_error, s.law_energy,
              100 * s.energy_discontinuity / s.crush_energy, (l1 - l0) / l_scale);
}

TEST(EnergyLedger, CarToCarDemo) { ExpectLedgerBalances(Demo("car_to_car_side.json"), "car to car"); }

TEST(EnergyLedger, CarToCarAtHalfAndFifthTimeStep) {
  for (int divisor : {2, 5}) {
    Scenario s = Demo("car_to_car_side.json");
    s.time_step /= divisor;
    ExpectLedgerBalances(s, "car to car dt/" + std::to_string(divisor));
  }
}

TEST(EnergyLedger, ObliqueAndOffset) {
  ExpectLedgerBalances(Demo("car_to_car_oblique.json"), "oblique 45 deg");
  ExpectLedgerBalances(Demo("car_to_car_offset.json"), "offset frontal");
}

TEST(EnergyLedger, PoleDemos) {
  // a rigid pole: fixed bodies take no momentum, so only the energy is checked there
  for (const char* name : {"pole.json", "pole_offset.json"}) {
    auto device = std::make_shared<const accel::EmbreeDevice>();
    Simulation sim(Demo(name), BuildBodyModels(Demo(name)), accel::MakeEmbreeLocatorFactory(device));
    sim.Run();
    const Summary s = Summarize(sim);
    const double lost = s.kinetic_before - s.kinetic_after;
    EXPECT_NEAR(s.crush_energy + s.friction_energy, lost, 0.02 * lost) << name;
    // one deformable side against a rigid one: the node law accounts for the crush work (2 %)
    EXPECT_NEAR(s.law_energy, s.crush_energy, 0.02 * s.crush_energy) << name;
    // the car backs off the pole and the contact ends within the demo's duration (the offset pole
    // kept its crushed front rubbing the pole's side before friction held and the corner re-search)
    EXPECT_TRUE(sim.separated()) << name;
    std::printf("[measured] %s: balance %.4f %%, node law / crush work %.4f\n", name, 100 * s.energy_balance_error,
                s.law_energy / s.crush_energy);
  }
}

// A `gravity` body's weight and ground support work on it: the kinetic energy lost is the contact's
// work less theirs (Summary::support_work), booked as the contact work is, at each step's mean velocity.
TEST(EnergyLedger, AGravityBodysWeightAndGroundSupportAreBooked) {
  // a kick upward with nothing to hit: the support takes the whole m v^2 / 2 as the body settles
  // (its speed falls as e^(-omega t), omega = 99 rad/s: after 0.4 s, 1e-17 of it)
  Scenario kicked = testing::BarrierScenario(0.0, 0.1, 0.0005);
  kicked.bodies[0].motion = MotionModel::kGravityGround;
  kicked.bodies[0].initial.velocity = Vec3(0.0, 0.0, -1.0);  // earth z down
  auto device = std::make_shared<const accel::EmbreeDevice>();
  Simulation settling(kicked, BuildBodyModels(kicked), accel::MakeEmbreeLocatorFactory(device));
  settling.Run();
  const double mass = settling.engine().model(0).mass;
  EXPECT_NEAR(Summarize(settling).support_work, -0.5 * mass, 1e-9 * mass);
  // the box into a frictionless wall pitched 30 deg: the wall's push has a vertical part, which the
  // support carries. The semi-implicit host changes the velocity by the step's force, so the work at
  // the mean velocity is exactly the kinetic energy's change; the bar, 1e-6, is what the rotation's
  // gyroscopic term leaves (it is booked at the mean rate; seen 3e-10). Before the support was booked
  // this run read its share of the energy lost, -2.1 %, voided by `energy_balance` (the sweep of
  // 2026-11-28: default-step gravity runs up to 0.78 %)
  Scenario pitched = testing::BarrierScenario(20.0, 0.1, 0.0005);
  pitched.bodies[0].motion = MotionModel::kGravityGround;
  for (BodySpec& b : pitched.bodies) b.friction = 0.0;
  // the wall's front face, 40 in deep and turned 30 deg, first meets the 30 in high box 1 in ahead of it
  const double pitch = 30.0 * 3.14159265358979323846 / 180.0;
  pitched.bodies[1].initial.pitch = pitch;
  pitched.bodies[1].initial.position.x() = (91.0 + 20.0 / std::cos(pitch) + 15.0 * std::tan(pitch)) * units::kInch;
  std::printf("[measured] kicked gravity box: support work %.6f of m v^2 / 2\n",
              Summarize(settling).support_work / (-0.5 * mass));
  // and across the step, the searches, the stop rule, passes, the box meshed 1:4, the wall listed first
  // and the frame turned: an identity of the host's update, so the same bar everywhere
  std::vector<testing::ScenarioVariant> variants = testing::ContactVariants();
  variants.insert(variants.begin(), {"default", [](Scenario*) {}});
  variants.push_back({"box meshed 1:4", [](Scenario* s) { s->bodies[0].mesh.subdivisions += 1; }});
  variants.push_back({"wall first", [](Scenario* s) { std::swap(s->bodies[0], s->bodies[1]); }});
  for (const testing::ScenarioVariant& variant : variants) {
    Scenario varied = pitched;
    variant.second(&varied);
    Simulation sim(varied, BuildBodyModels(varied), accel::MakeEmbreeLocatorFactory(device));
    sim.Run();
    const Summary s = Summarize(sim);
    const double lost = s.kinetic_before - s.kinetic_after;
    ASSERT_GT(s.crush_energy, 0.5 * s.kinetic_before) << variant.first << ": a real collision";
    EXPECT_GT(std::abs(s.support_work), 1e-3 * lost) << variant.first << ": the support worked";
    EXPECT_LT(std::abs(s.energy_balance_error), 1e-6) << variant.first;
    std::printf("[measured] gravity box into the pitched wall, %s: support work %.3f %% of the kinetic energy "
                "lost, balance %.2e\n", variant.first.c_str(), 100.0 * s.support_work / lost, s.energy_balance_error);
  }
}

}  // namespace
}  // namespace dymesh
