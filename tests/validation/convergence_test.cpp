// Time-step and mesh convergence of delta-V in a car-to-car collision on real meshes.
#include <gtest/gtest.h>

#include <cstdio>

#include "dymesh/accel/embree_locator.h"
#include "dymesh/core/results.h"
#include "dymesh/core/simulation.h"

namespace dymesh {
namespace {

Scenario CarToCar() {
  return LoadScenario(std::string(DYMESH_DATA_DIR) + "/scenarios/car_to_car_side.json");
}

std::vector<double> DeltaVs(const Scenario& scenario) {
  auto device = std::make_shared<const EmbreeDevice>();
  Simulation sim(scenario, MakeEmbreeLocatorFactory(device));
  sim.Run();
  const Summary s = Summarize(sim);
  return {s.bodies[0].delta_v, s.bodies[1].delta_v};
}

// the criterion: a refinement changes each delta-V by under 2 %
void ExpectWithinTwoPercent(const std::vector<double>& coarse, const std::vector<double>& fine) {
  for (size_t i = 0; i < coarse.size(); ++i) {
    EXPECT_GT(coarse[i], 0.5);  // a real collision, not two near misses [m/s]
    EXPECT_NEAR(fine[i], coarse[i], 0.02 * coarse[i]) << "body " << i;
    std::printf("[measured] body %zu delta-V %.4f -> %.4f m/s (%.2f %%)\n", i, coarse[i], fine[i],
                100 * (fine[i] - coarse[i]) / coarse[i]);
  }
}

TEST(Convergence, HalvingTheTimeStep) {
  const Scenario base = CarToCar();
  Scenario half = base;
  half.time_step = base.time_step / 2;
  ExpectWithinTwoPercent(DeltaVs(base), DeltaVs(half));
}

TEST(Convergence, SubdividingTheMeshes) {
  const Scenario base = CarToCar();
  Scenario fine = base;
  for (BodySpec& b : fine.bodies) b.mesh.subdivisions += 1;  // four times the triangles
  ExpectWithinTwoPercent(DeltaVs(base), DeltaVs(fine));
}

}  // namespace
}  // namespace dymesh
