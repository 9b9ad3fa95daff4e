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
#include "dymesh/analysis/summary.h"
#include "dymesh/core/simulation.h"
#include "test_scenarios.h"

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

// the offset pole: nodes pressed on the pole's front used to be found behind its side face as the car
// stopped and be loaded sideways with their whole crush, one step of ~20,000 lbf (alternation 18 %
// of the peak). Checked for every search method, and for the velocity search with the car's mesh
// 1:4, three passes, the pole listed first and the frame turned 30 degrees; each at dt and dt/2, with
// its energy balance (2 %, the bar)
void ExpectOffsetPoleSmooth(const char* label, const std::function<void(Scenario*)>& vary) {
  Scenario s = LoadScenario(std::string(DYMESH_DATA_DIR) + "/scenarios/pole_offset.json");
  vary(&s);
  const int car = s.bodies[0].rigid ? 1 : 0;
  for (double divide : {1.0, 2.0}) {
    Scenario run = s;
    run.time_step /= divide;
    auto device = std::make_shared<const accel::EmbreeDevice>();
    Simulation sim(run, BuildBodyModels(run), accel::MakeEmbreeLocatorFactory(device));
    sim.Run();
    std::vector<double> f;
    for (const Sample& sample : sim.history()) f.push_back(sample.bodies[car].loads.force_earth.norm());
    const double peak = *std::max_element(f.begin(), f.end());
    const double balance = Summarize(sim).energy_balance_error;
    EXPECT_LT(Alternation(f), kMaxAlternation * peak) << label << " dt/" << divide;
    EXPECT_NEAR(balance, 0.0, 0.02) << label << " dt/" << divide;
    std::printf("[measured] pole_offset.json, %s, dt/%.0f: alternation %.3f of the peak %.0f N, balance %.4f %%\n",
                label, divide, Alternation(f) / peak, peak, 100 * balance);
  }
}

TEST(Pulse, OffsetPoleDoesNotChatterForAnySearchDirection) {
  ExpectOffsetPoleSmooth("velocity", [](Scenario*) {});
  ExpectOffsetPoleSmooth("local_average_normal",
                         [](Scenario* s) { s->contact.search_direction = SearchDirection::kLocalAverageNormal; });
  ExpectOffsetPoleSmooth("poly_normal", [](Scenario* s) { s->contact.search_direction = SearchDirection::kPolyNormal; });
}

TEST(Pulse, OffsetPoleDoesNotChatterOnAFinerMeshMorePassesOtherOrderTurnedFrame) {
  ExpectOffsetPoleSmooth("car mesh 1:4", [](Scenario* s) { s->bodies[0].mesh.subdivisions += 1; });
  ExpectOffsetPoleSmooth("3 passes", [](Scenario* s) { s->contact.passes_per_step = 3; });
  ExpectOffsetPoleSmooth("pole first", [](Scenario* s) { std::swap(s->bodies[0], s->bodies[1]); });
  ExpectOffsetPoleSmooth("frame +30 deg", [](Scenario* s) {
    for (BodySpec& b : s->bodies) testing::TurnAboutVertical(30.0 * units::kDegree, &b);
  });
}

// spec §7 friction in the pulse: a box (180 x 66 x 50 in, 3000 lb, A 350, B 125) at 30 mph into the side
// of another (192 x 77 x 50 in, 3400 lb, A 200, B 75) 40 in behind its centre, mu 0.5, e 0.1: the struck
// box turns at 165 deg/s and the fronts slide across each other as they crush. Friction read against
// the slide the normal loads alone leave overshot it, pushing the slide the other way the next step:
// it alternated between about mu N and half of it, by 6.0 / 5.5 / 4.1 % of the peak at dt, dt/2 and
// dt/4, and the peak fell 4.6 % at dt/2 and 9.5 % at dt/4 (69th session, before friction was read
// against the slide it leaves). Known answer: the converged pulse. Its peak at dt/2 and dt/4 within
// 2 % of dt's (the bar; measured +0.29 and +0.32 %) and no alternation over 2 % of it
// (measured 0.5-0.9 %; the bar lies between that and the 4-6 % of the friction it replaced)
Scenario FrictionalSideImpactOfBoxes() {
  Scenario s = testing::UsScenario("(frictional side impact)", 0.0005, 0.5);
  BodySpec bullet = testing::BoxVehicle("bullet", 180, 66, 50, {36, 22, 10}, 3000, 350, 125, 50, 0.1);
  bullet.initial.position = Vec3(-130, -40, 0) * units::kInch;
  bullet.initial.velocity = Vec3(30, 0, 0) * units::kMph;
  BodySpec target = testing::BoxVehicle("target", 192, 77, 50, {48, 22, 10}, 3400, 200, 75, 50, 0.1);
  target.initial.yaw = 90.0 * units::kDegree;
  bullet.friction = target.friction = 0.5;
  s.bodies = {bullet, target};
  return s;
}

TEST(Pulse, FrictionalSideImpactOfBoxesConvergesInTheStep) {
  const Scenario s = FrictionalSideImpactOfBoxes();
  double peak_at_dt = 0.0;
  for (double divide : {1.0, 2.0, 4.0}) {
    Scenario run = s;
    run.time_step = s.time_step / divide;
    const std::vector<double> f = ForceSeries(run);
    const double peak = *std::max_element(f.begin(), f.end());
    if (divide == 1.0) peak_at_dt = peak;
    EXPECT_LT(Alternation(f), 0.02 * peak) << "dt/" << divide;
    EXPECT_NEAR(peak, peak_at_dt, 0.02 * peak_at_dt) << "dt/" << divide;
    std::printf("[measured] frictional side impact of boxes, dt/%.0f: alternation %.4f of the peak %.0f N (%+.2f %% of dt's)\n",
                divide, Alternation(f) / peak, peak, 100 * (peak / peak_at_dt - 1));
  }
}

// the same impact across the contact options, the bullet's mesh 1:4 and the body order, each with its
// energy balance: no alternation over 2 % of the peak (measured 0.1-0.9 %), but with the polygon-normal
// search and 3 passes, which alternate without friction too (mu 0: 5.7 and 4.2 %; with it 7.3 and
// 3.1 %), held to the demos' 15 %; the bullet's delta-V within 2 % of the default's (the bar;
// measured within 0.7 %), bit for bit with the order swapped; the ledger balanced to round-off
// (measured 3e-15)
TEST(Pulse, FrictionalSideImpactOfBoxesAcrossContactOptions) {
  const Scenario base = FrictionalSideImpactOfBoxes();
  auto variants = testing::ContactVariants();
  variants.push_back({"bullet mesh 1:4", [](Scenario* s) { s->bodies[0].mesh.subdivisions += 1; }});
  variants.push_back({"order swapped", [](Scenario* s) { std::swap(s->bodies[0], s->bodies[1]); }});
  variants.insert(variants.begin(), {"default", [](Scenario*) {}});
  double reference_dv = 0.0;
  for (const auto& [label, vary] : variants) {
    Scenario run = base;
    vary(&run);
    auto device = std::make_shared<const accel::EmbreeDevice>();
    Simulation sim(run, BuildBodyModels(run), accel::MakeEmbreeLocatorFactory(device));
    sim.Run();
    std::vector<double> f;
    for (const Sample& sample : sim.history()) f.push_back(sample.bodies[0].loads.force_earth.norm());
    const double peak = *std::max_element(f.begin(), f.end());
    const Summary summary = Summarize(sim);
    const double dv = summary.bodies[run.bodies[0].name == "bullet" ? 0 : 1].delta_v;
    if (label == "default") reference_dv = dv;
    const bool alternates_without_friction = label == "polygon normal" || label == "3 passes";
    EXPECT_LT(Alternation(f), (alternates_without_friction ? kMaxAlternation : 0.02) * peak) << label;
    EXPECT_NEAR(summary.energy_balance_error, 0.0, 1e-9) << label;
    EXPECT_NEAR(dv, reference_dv, 0.02 * reference_dv) << label;
    if (label == "order swapped") {
      EXPECT_EQ(dv, reference_dv);
    }
    std::printf("[measured] frictional side impact of boxes, %s: alternation %.4f of the peak %.0f N, bullet delta-V "
                "%+.2f %%, balance %.1e\n",
                label.c_str(), Alternation(f) / peak, peak, 100 * (dv / reference_dv - 1), summary.energy_balance_error);
  }
}

}  // namespace
}  // namespace dymesh
