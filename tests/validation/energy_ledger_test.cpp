// The energy ledger (LS-DYNA-style contact energy) and the conservation laws on the demos, the
// oblique and offset impacts, and at smaller time steps.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "dymesh/io/scenario_json.h"
#include "dymesh/io/body_models.h"
#include "dymesh/accel/embree_locator.h"
#include "dymesh/analysis/summary.h"
#include "dymesh/core/simulation.h"

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

}  // namespace
}  // namespace dymesh
