// The collision pulse: no step-to-step alternation of the contact force on the demos.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <utility>
#include <string>

#include "dymesh/io/scenario_json.h"
#include "dymesh/io/body_models.h"
#include "dymesh/accel/embree_locator.h"
#include "dymesh/core/contact_step.h"
#include "dymesh/core/rigid_body.h"
#include "dymesh/core/simulation.h"

namespace dymesh {
namespace {

// resultant collision force on body 0 per step [N]
std::vector<double> ForceSeries(const Scenario& scenario) {
  auto device = std::make_shared<const accel::EmbreeDevice>();
  Simulation sim(scenario, BuildBodyModels(scenario), accel::MakeEmbreeLocatorFactory(device));
  sim.Run();
  std::vector<double> f;
  for (const Sample& s : sim.history()) f.push_back(s.bodies[0].loads.force_earth.norm());
  return f;
}

// a host loop over the engine (the library's seam) on `scenario`; after each step `check` sees the
// step's loads and the states before and after the host moved the bodies
using StepCheck = std::function<void(const ContactEngine&, const StepResult&, const std::vector<RigidState>& before)>;
void RunHostLoop(const Scenario& scenario, const StepCheck& check) {
  auto device = std::make_shared<const accel::EmbreeDevice>();
  std::vector<RigidState> initial;
  for (const BodySpec& b : scenario.bodies) initial.push_back(b.initial);
  ContactEngine engine(BuildBodyModels(scenario), initial, scenario.contact, accel::MakeEmbreeLocatorFactory(device));
  for (int i = 0; i < engine.body_count(); ++i) engine.SetMotion(i, scenario.bodies[i].motion);
  const int steps = static_cast<int>(std::lround(scenario.duration / scenario.time_step));
  for (int step = 0; step < steps; ++step) {
    const StepResult r = engine.Step(scenario.time_step);
    std::vector<RigidState> before;
    for (int i = 0; i < engine.body_count(); ++i) {
      before.push_back(engine.state(i).rigid);
      RigidState rigid = before.back();
      IntegrateRigidBody(engine.model(i), scenario.bodies[i].motion, r.loads[i].force_earth, r.loads[i].moment_body,
                         scenario.time_step, &rigid);
      engine.SetRigidState(i, rigid);
    }
    check(engine, r, before);
  }
}

// chatter: the largest alternating part of the series, i.e. over every step where the force goes up
// then down (or down then up), the smaller of the two changes; a single jump (contact onset, the
// unloading drop of spec §6) is not chatter and does not count
double Alternation(const std::vector<double>& f) {
  double worst = 0.0;
  for (std::size_t i = 1; i + 1 < f.size(); ++i) {
    const double before = f[i] - f[i - 1], after = f[i + 1] - f[i];
    if (before * after < 0.0) worst = std::max(worst, std::min(std::abs(before), std::abs(after)));
  }
  return worst;
}

// under 15 % of the peak: discrete nodes entering and leaving contact on meshes of 8.5k and 4.5k
// triangles leave at most 12 % (measured); the engine before this bar alternated by about a fifth of
// the peak on the side-impact demo while unloading
constexpr double kMaxAlternation = 0.15;

void ExpectSmooth(const std::string& name) {
  const Scenario s = LoadScenario(std::string(DYMESH_DATA_DIR) + "/scenarios/" + name);
  const std::vector<double> f = ForceSeries(s);
  const double peak = *std::max_element(f.begin(), f.end());
  ASSERT_GT(peak, 0.0) << name;
  EXPECT_LT(Alternation(f), kMaxAlternation * peak) << name;
  Scenario half = s;
  half.time_step /= 2;
  const std::vector<double> g = ForceSeries(half);
  const double peak_half = *std::max_element(g.begin(), g.end());
  std::printf("[measured] %s: alternation %.3f of the peak %.0f N; peak at dt/2 %+.1f %%\n", name.c_str(),
              Alternation(f) / peak, peak, 100 * (peak_half / peak - 1));
}

TEST(Pulse, SideImpactDemoDoesNotChatter) { ExpectSmooth("car_to_car_side.json"); }
TEST(Pulse, PoleDemoDoesNotChatter) { ExpectSmooth("pole.json"); }
TEST(Pulse, ObliqueDoesNotChatter) { ExpectSmooth("car_to_car_oblique.json"); }

// the offset pole, for every ray search method (and the triangle-normal one): nodes pressed on the
// pole's front used to be found behind its side face as the car stopped and be loaded sideways with
// their whole crush, one step of ~20,000 lbf (alternation 18 % of the peak)
TEST(Pulse, OffsetPoleDoesNotChatterForAnySearchDirection) {
  const std::pair<SearchDirection, const char*> methods[] = {{SearchDirection::kVelocity, "velocity"},
                                                             {SearchDirection::kLocalAverageNormal, "local_average_normal"},
                                                             {SearchDirection::kPolyNormal, "poly_normal"}};
  for (const auto& [direction, name] : methods) {
    Scenario s = LoadScenario(std::string(DYMESH_DATA_DIR) + "/scenarios/pole_offset.json");
    s.contact.search_direction = direction;
    for (double divide : {1.0, 2.0}) {
      Scenario run = s;
      run.time_step /= divide;
      const std::vector<double> f = ForceSeries(run);
      const double peak = *std::max_element(f.begin(), f.end());
      EXPECT_LT(Alternation(f), kMaxAlternation * peak) << name << " dt/" << divide;
      std::printf("[measured] pole_offset.json, %s, dt/%.0f: alternation %.3f of the peak %.0f N\n", name, divide,
                  Alternation(f) / peak, peak);
    }
  }
}

// spec §7 Coulomb friction stops a slide but never reverses it: the friction loads of a step, acting
// alone on the bodies as the host moves them, leave no motion against which they would push the
// other way (their power on the step-end motion is not positive). The offset pole holds the car's
// front with mu 0.5: mu N (15,000 lbf) used to reverse the slide within one step
TEST(Friction, StopsASlideWithoutReversingIt) {
  const Scenario s = LoadScenario(std::string(DYMESH_DATA_DIR) + "/scenarios/pole_offset.json");
  int limited = 0;
  RunHostLoop(s, [&](const ContactEngine& engine, const StepResult& r, const std::vector<RigidState>& before) {
    for (const PairLoads& p : r.pairs) {
      double power_before = 0.0, power_after = 0.0, scale = 0.0;  // [W]
      for (int k = 0; k < 2; ++k) {
        // the step-start motion, and that motion moved by the friction loads alone
        const int body = p.body[k];
        RigidState moved = before[body];
        IntegrateRigidBody(engine.model(body), s.bodies[body].motion, p.friction_force[k],
                           moved.Rotation().transpose() * p.friction_moment[k], s.time_step, &moved);
        const RigidState& b = before[body];
        power_before += p.friction_force[k].dot(b.velocity) + p.friction_moment[k].dot(b.Rotation() * b.omega);
        power_after += p.friction_force[k].dot(moved.velocity) + p.friction_moment[k].dot(b.Rotation() * moved.omega);
        scale += std::abs(p.friction_force[k].dot(b.velocity)) + 1e-9;
      }
      // round-off of the power sums: 1e-9 of their terms
      EXPECT_LE(power_after, 1e-9 * scale);
      if (power_before < 0.0 && std::abs(power_after) <= 1e-9 * scale) ++limited;
    }
  });
  EXPECT_GT(limited, 10);  // the limit really acts on this run
  std::printf("[measured] pole_offset.json: friction limited to stopping the slide on %d steps\n", limited);
}

// friction that has slowed or stopped a slide holds it: the spec's null band (no friction below
// 1 in/s) is for slides too slow to matter, not for one friction itself brought there. On the offset
// pole the car's front is held by the pole's face (mu 0.5) while it crushes; with the band alone the
// lateral friction switched between mu N (or the force that stops the slide) and nothing every second
// or third step through the loading phase. Counted here: steps where the friction falls below a
// tenth of the step before and rises again after
TEST(Friction, HoldsTheSlideItStoppedWithoutSwitchingOff) {
  const Scenario s = LoadScenario(std::string(DYMESH_DATA_DIR) + "/scenarios/pole_offset.json");
  std::vector<double> f;
  RunHostLoop(s, [&](const ContactEngine&, const StepResult& r, const std::vector<RigidState>&) {
    Vec3 friction = Vec3::Zero();
    for (const PairLoads& p : r.pairs) friction += p.friction_force[p.body[0] == 0 ? 0 : 1];
    f.push_back(friction.norm());
  });
  int switches = 0;
  for (std::size_t i = 1; i + 1 < f.size(); ++i) {
    if (f[i] < 0.1 * f[i - 1] && f[i] < 0.1 * f[i + 1]) ++switches;
  }
  EXPECT_EQ(switches, 0);
  std::printf("[measured] pole_offset.json: friction switched off for single steps %d times\n", switches);
}

}  // namespace
}  // namespace dymesh
