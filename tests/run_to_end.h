#pragma once
// A scenario run to its end on the Embree locator and summarised: the validation tests' common run.
#include <memory>

#include "dymesh/accel/embree_locator.h"
#include "dymesh/analysis/summary.h"
#include "dymesh/core/simulation.h"
#include "dymesh/io/body_models.h"

namespace dymesh::testing {

inline Summary RunToEnd(const Scenario& scenario) {
  auto device = std::make_shared<const accel::EmbreeDevice>();
  Simulation sim(scenario, BuildBodyModels(scenario), accel::MakeEmbreeLocatorFactory(device));
  sim.Run();
  return Summarize(sim);
}

}  // namespace dymesh::testing
