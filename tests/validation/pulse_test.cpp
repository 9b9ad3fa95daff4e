// The collision pulse: no step-to-step alternation of the contact force on the demos.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <string>

#include "dymesh/io/scenario_json.h"
#include "dymesh/io/body_models.h"
#include "dymesh/accel/embree_locator.h"
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

}  // namespace
}  // namespace dymesh
