// Force-provider mode: a host that integrates the bodies itself with the loads HostStep returns gets
// the same run as Simulation::Run when it integrates the same way: bit-identical history, crush and
// summary (the summary, the report and the outputs work from a host-driven run).
#include <gtest/gtest.h>

#include "dymesh/accel/embree_locator.h"
#include "dymesh/analysis/summary.h"
#include "dymesh/io/body_models.h"
#include "dymesh/io/scenario_json.h"
#include "dymesh/io/summary_json.h"

namespace dymesh {
namespace {

// the host: the engine's own semi-implicit integrator, driven from outside
void RunAsHost(Simulation* sim) {
  const Scenario& s = sim->scenario();
  std::vector<RigidState> states;
  for (int i = 0; i < sim->engine().body_count(); ++i) states.push_back(sim->engine().state(i).rigid);
  for (int step = 0; step < static_cast<int>(s.duration / s.time_step + 0.5); ++step) {
    const StepResult r = sim->HostStep(states, s.time_step);
    for (int i = 0; i < sim->engine().body_count(); ++i) {
      const BodyModel& m = sim->engine().model(i);
      const ExternalLoads extra = MotionModelLoads(s.bodies[i].motion, m, states[i], s.bodies[i].initial.position.z());
      IntegrateRigidBody(m, s.bodies[i].motion, r.loads[i].force_earth + extra.force_earth,
                         r.loads[i].moment_body + extra.moment_body, s.time_step, &states[i]);
    }
  }
  sim->FinishHostRun(states);
}

TEST(HostMode, SameRunAsTheEnginesOwnHost) {
  Scenario s = LoadScenario(std::string(DYMESH_DATA_DIR) + "/scenarios/car_to_car_side.json");
  s.stop_at_separation = false;  // the host decides when to stop: the full duration in both
  const auto models = BuildBodyModels(s);
  auto device = std::make_shared<const accel::EmbreeDevice>();
  Simulation own(s, models, accel::MakeEmbreeLocatorFactory(device));
  own.Run();
  Simulation hosted(s, models, accel::MakeEmbreeLocatorFactory(device));
  RunAsHost(&hosted);
  ASSERT_EQ(hosted.history().size(), own.history().size());
  for (std::size_t k = 0; k < own.history().size(); ++k)
    for (int i = 0; i < 2; ++i) {
      ASSERT_EQ(hosted.history()[k].bodies[i].rigid.velocity, own.history()[k].bodies[i].rigid.velocity) << k;
      ASSERT_EQ(hosted.history()[k].bodies[i].loads.force_body, own.history()[k].bodies[i].loads.force_body) << k;
      ASSERT_EQ(hosted.history()[k].bodies[i].crush_energy, own.history()[k].bodies[i].crush_energy) << k;
    }
  EXPECT_EQ(SummaryJson(Summarize(hosted), s, {}), SummaryJson(Summarize(own), s, {}));
}

// a host whose bodies are not where construction put them when it first calls: the run starts from
// the host's states. The barrier car, placed touching the wall, comes in at 1.2 times the scenario's
// speed: the pair closes at that speed (the wall is fixed; round-off bar) and the car's delta-V is
// taken from it
TEST(HostMode, TheRunStartsFromTheHostsFirstStates) {
  Scenario s = LoadScenario(std::string(DYMESH_DATA_DIR) + "/scenarios/barrier_frontal.json");
  Simulation sim(s, BuildBodyModels(s), accel::MakeEmbreeLocatorFactory(std::make_shared<const accel::EmbreeDevice>()));
  std::vector<RigidState> states = {sim.engine().state(0).rigid, sim.engine().state(1).rigid};
  const double host_speed = 1.2 * states[0].velocity.norm();
  states[0].velocity *= 1.2;
  const RigidState host_start = states[0];
  for (int step = 0; step < 10; ++step) {
    const StepResult r = sim.HostStep(states, s.time_step);
    IntegrateRigidBody(sim.engine().model(0), s.bodies[0].motion, r.loads[0].force_earth, r.loads[0].moment_body,
                       s.time_step, &states[0]);
  }
  sim.FinishHostRun(states);
  EXPECT_EQ(sim.history().front().bodies[0].rigid.velocity, host_start.velocity);
  const Summary summary = Summarize(sim);
  ASSERT_EQ(summary.pairs.size(), 1u);
  EXPECT_NEAR(summary.pairs[0].closing_speed, host_speed, 1e-12 * host_speed);
  EXPECT_NEAR(summary.bodies[0].delta_v, (states[0].velocity - host_start.velocity).norm(), 1e-12 * host_speed);
}

TEST(HostMode, RefusesWrongCountsNonFiniteStatesAndBadSteps) {
  Scenario s = LoadScenario(std::string(DYMESH_DATA_DIR) + "/scenarios/barrier_frontal.json");
  Simulation sim(s, BuildBodyModels(s), accel::MakeEmbreeLocatorFactory(std::make_shared<const accel::EmbreeDevice>()));
  std::vector<RigidState> states = {sim.engine().state(0).rigid, sim.engine().state(1).rigid};
  EXPECT_THROW(sim.HostStep({states[0]}, 0.0005), std::invalid_argument);
  EXPECT_THROW(sim.HostStep(states, 0.0), std::invalid_argument);
  EXPECT_THROW(sim.HostStep(states, -1.0), std::invalid_argument);
  states[0].velocity.x() = std::nan("");
  EXPECT_THROW(sim.HostStep(states, 0.0005), std::invalid_argument);
  states[0] = sim.engine().state(0).rigid;
  EXPECT_NO_THROW(sim.HostStep(states, 0.0005));
  sim.FinishHostRun(states);
  EXPECT_THROW(sim.HostStep(states, 0.0005), std::logic_error);
}

TEST(HostMode, ContactEngineRefusesMismatchedPosesBadIndicesNonFiniteStatesAndBadSteps) {
  Scenario s = LoadScenario(std::string(DYMESH_DATA_DIR) + "/scenarios/barrier_frontal.json");
  const auto models = BuildBodyModels(s);
  const auto factory = accel::MakeEmbreeLocatorFactory(std::make_shared<const accel::EmbreeDevice>());
  EXPECT_THROW(ContactEngine(models, {s.bodies[0].initial}, s.contact, factory), std::invalid_argument);
  RigidState nan_pose = s.bodies[0].initial;
  nan_pose.yaw = std::nan("");
  EXPECT_THROW(ContactEngine(models, {nan_pose, s.bodies[1].initial}, s.contact, factory), std::invalid_argument);
  ContactEngine engine(models, {s.bodies[0].initial, s.bodies[1].initial}, s.contact, factory);
  EXPECT_THROW(engine.SetRigidState(2, s.bodies[0].initial), std::invalid_argument);
  EXPECT_THROW(engine.SetRigidState(-1, s.bodies[0].initial), std::invalid_argument);
  EXPECT_THROW(engine.SetRigidState(0, nan_pose), std::invalid_argument);
  EXPECT_THROW(engine.SetMotion(2, MotionModel::kPlanar), std::invalid_argument);
  EXPECT_THROW(engine.SetMotion(-1, MotionModel::kFixed), std::invalid_argument);
  EXPECT_THROW(engine.Step(0.0), std::invalid_argument);
  EXPECT_THROW(engine.Step(-0.001), std::invalid_argument);
  EXPECT_NO_THROW(engine.Step(0.0005));
}

}  // namespace
}  // namespace dymesh
