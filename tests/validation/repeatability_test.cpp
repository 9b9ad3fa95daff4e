// Repeating a run gives bit-identical outputs.
#include <gtest/gtest.h>

#include "dymesh/io/summary_json.h"
#include "dymesh/io/scenario_json.h"
#include "dymesh/io/body_models.h"
#include "dymesh/accel/embree_locator.h"
#include "dymesh/analysis/summary.h"
#include "dymesh/core/simulation.h"

namespace dymesh {
namespace {

TEST(Repeatability, SameScenarioTwiceIsBitIdentical) {
  Scenario scenario = LoadScenario(std::string(DYMESH_DATA_DIR) + "/scenarios/car_to_car_side.json");
  scenario.duration = 0.08;
  auto device = std::make_shared<const accel::EmbreeDevice>();
  Simulation first(scenario, BuildBodyModels(scenario), accel::MakeEmbreeLocatorFactory(device));
  Simulation second(scenario, BuildBodyModels(scenario), accel::MakeEmbreeLocatorFactory(device));
  first.Run();
  second.Run();
  ASSERT_EQ(first.history().size(), second.history().size());
  // every recorded quantity and every vertex of every body, compared with ==
  for (size_t k = 0; k < first.history().size(); ++k) {
    for (size_t i = 0; i < first.history()[k].bodies.size(); ++i) {
      const BodySample& a = first.history()[k].bodies[i];
      const BodySample& b = second.history()[k].bodies[i];
      ASSERT_EQ(a.rigid.position, b.rigid.position);
      ASSERT_EQ(a.rigid.velocity, b.rigid.velocity);
      ASSERT_EQ(a.rigid.omega, b.rigid.omega);
      ASSERT_EQ(a.loads.force_body, b.loads.force_body);
      ASSERT_EQ(a.loads.moment_body, b.loads.moment_body);
      ASSERT_EQ(a.crush_energy, b.crush_energy);
    }
  }
  for (int i = 0; i < first.engine().body_count(); ++i) {
    EXPECT_EQ(first.engine().state(i).vertices, second.engine().state(i).vertices);
    EXPECT_EQ(first.engine().state(i).delta_max, second.engine().state(i).delta_max);
  }
  EXPECT_EQ(SummaryJson(Summarize(first), scenario, {}), SummaryJson(Summarize(second), scenario, {}));
  EXPECT_GT(Summarize(first).bodies[0].crush_energy, 0.0);
}

}  // namespace
}  // namespace dymesh
