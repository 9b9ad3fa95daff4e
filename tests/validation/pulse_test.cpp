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

}  // namespace
}  // namespace dymesh
