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

// the host: the engine's own semi-implicit integrator, driven from outside, `steps` steps of `dt`
void RunAsHost(Simulation* sim, double dt, int steps) {
  const Scenario& s = sim->scenario();
  std::vector<RigidState> states;
  for (int i = 0; i < sim->engine().body_count(); ++i) states.push_back(sim->engine().state(i).rigid);
  for (int step = 0; step < steps; ++step) {
    const StepResult r = sim->HostStep(states, dt);
    for (int i = 0; i < sim->engine().body_count(); ++i) {
      const BodyModel& m = sim->engine().model(i);
      const ExternalLoads extra = MotionModelLoads(s.bodies[i].motion, m, states[i], s.bodies[i].initial.position.z());
      IntegrateRigidBody(m, s.bodies[i].motion, r.loads[i].force_earth + extra.force_earth,
                         r.loads[i].moment_body + extra.moment_body, dt, &states[i]);
    }
  }
  sim->FinishHostRun(states);
}

// the scenario's own step over its duration
void RunAsHost(Simulation* sim) {
  const Scenario& s = sim->scenario();
  RunAsHost(sim, s.time_step, static_cast<int>(s.duration / s.time_step + 0.5));
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
  EXPECT_EQ(hosted.host_motion_mismatch().body, -1);
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
  // beyond the physical ranges (a fuzz of host mode, 2026-11-28: -1e150 m/s ran to 1.4e151 J of crush)
  const auto refused = [&](auto&& change) {
    std::vector<RigidState> bad = {sim.engine().state(0).rigid, sim.engine().state(1).rigid};
    change(&bad[0]);
    EXPECT_THROW(sim.HostStep(bad, 0.0005), std::invalid_argument);
  };
  refused([](RigidState* r) { r->velocity.x() = -1e150; });
  refused([](RigidState* r) { r->position.y() = 1e200; });
  refused([](RigidState* r) { r->yaw = 1e300; });
  refused([](RigidState* r) { r->omega.z() = 1e4; });
  states[0] = sim.engine().state(0).rigid;
  EXPECT_NO_THROW(sim.HostStep(states, 0.0005));
  sim.FinishHostRun(states);
  EXPECT_THROW(sim.HostStep(states, 0.0005), std::logic_error);
}

bool HasWarning(const Summary& s, const std::string& code) {
  for (const RunWarning& w : s.warnings)
    if (w.code == code) return true;
  return false;
}

// a host whose states the contact's work cannot be booked from is marked (found by a fuzz of host mode,
// 2026-11-28): the side demo's cars held 0.3 m into each other at their speeds for 200 steps (the host
// integrating nothing) read a perfect energy balance, 0.0, over 28 kJ of crush work; the barrier car
// pushed 2 mm into the wall each step while reported at rest read no warning at all (nor, until the
// turn was compared too, one turned 0.01 rad a step while reported not turning); a host dt of
// 0.03 s was judged by the scenario's 0.5 ms step
TEST(HostMode, AHostWhoseStatesDoNotBookTheWorkIsMarked) {
  auto device = std::make_shared<const accel::EmbreeDevice>();
  Scenario side = LoadScenario(std::string(DYMESH_DATA_DIR) + "/scenarios/car_to_car_side.json");
  side.stop_at_separation = false;
  Simulation held(side, BuildBodyModels(side), accel::MakeEmbreeLocatorFactory(device));
  std::vector<RigidState> states = {held.engine().state(0).rigid, held.engine().state(1).rigid};
  const Vec3 into = (states[1].position - states[0].position).normalized();
  // the same states every step: velocities held, positions held (0 m moved, velocities account for
  // their v dt: also inconsistent), kinetic energy unchanged
  states[0].position += 0.3 * into;
  for (int step = 0; step < 200; ++step) held.HostStep(states, side.time_step);
  held.FinishHostRun(states);
  const Summary h = Summarize(held);
  EXPECT_GT(h.crush_energy, 1000.0);
  EXPECT_EQ(h.energy_balance_error, -1.0);  // work with no kinetic energy lost
  EXPECT_TRUE(HasWarning(h, "energy_balance"));
  EXPECT_TRUE(HasWarning(h, "host_motion_inconsistent"));
  // at rest, pushed 2 mm a step: moved 2 mm where the velocities account for none
  Scenario barrier = LoadScenario(std::string(DYMESH_DATA_DIR) + "/scenarios/barrier_frontal.json");
  Simulation pushed(barrier, BuildBodyModels(barrier), accel::MakeEmbreeLocatorFactory(device));
  states = {pushed.engine().state(0).rigid, pushed.engine().state(1).rigid};
  states[0].velocity.setZero();
  for (int step = 0; step < 20; ++step) {
    pushed.HostStep(states, barrier.time_step);
    states[0].position.x() += 0.002;
  }
  pushed.FinishHostRun(states);
  const HostMotionMismatch& m = pushed.host_motion_mismatch();
  EXPECT_EQ(m.body, 0);
  EXPECT_NEAR(m.moved, 0.002, 1e-12);
  EXPECT_EQ(m.accounted, 0.0);
  EXPECT_TRUE(HasWarning(Summarize(pushed), "host_motion_inconsistent"));
  // at rest, turned 0.01 rad a step about the vertical while reported not turning (until 2026-11-28
  // only the CG's motion was compared): its farthest point, r from the CG, moved 0.01 r where the
  // rates account for none
  Simulation turned(barrier, BuildBodyModels(barrier), accel::MakeEmbreeLocatorFactory(device));
  states = {turned.engine().state(0).rigid, turned.engine().state(1).rigid};
  states[0].velocity.setZero();
  double r = 0.0;
  for (const Vec3& p : turned.engine().model(0).mesh.vertices) r = std::max(r, p.norm());
  for (int step = 0; step < 20; ++step) {
    turned.HostStep(states, barrier.time_step);
    states[0].yaw += 0.01;
  }
  turned.FinishHostRun(states);
  const HostMotionMismatch& t = turned.host_motion_mismatch();
  EXPECT_EQ(t.body, 0);
  EXPECT_NEAR(t.moved, 0.01 * r, 1e-9 * r);
  EXPECT_EQ(t.accounted, 0.0);
  EXPECT_TRUE(HasWarning(Summarize(turned), "host_motion_inconsistent"));
  // a coarse host step is judged as the scenario's would be; a host that integrates its loads with
  // the engine's own host (SameRunAsTheEnginesOwnHost) is not warned of its motion
  barrier.time_step = 0.03;
  barrier.duration = 0.3;
  Simulation coarse(LoadScenario(std::string(DYMESH_DATA_DIR) + "/scenarios/barrier_frontal.json"),
                    BuildBodyModels(barrier), accel::MakeEmbreeLocatorFactory(device));
  RunAsHost(&coarse, barrier.time_step, 10);
  const Summary c = Summarize(coarse);
  EXPECT_EQ(coarse.largest_step(), 0.03);
  EXPECT_TRUE(HasWarning(c, "time_step_coarse"));
  EXPECT_TRUE(HasWarning(c, "step_beyond_search_reach"));
  EXPECT_FALSE(HasWarning(c, "host_motion_inconsistent"));
}

// the end-of-run windows (at rest in contact: the load not growing over the last 0.02 s; a light touch
// over the last 0.02 s) are judged over 0.02 s of the host's steps, not over as many steps as the
// scenario's own step makes 0.02 s (until 2026-11-28: 40 host steps of 2 ms, 0.08 s). The barrier car,
// held 20 mm into the wall (A), pressed 1.6 mm further at 0.04 m/s (B, under the 0.05 m/s rest speed),
// then held for 0.03 s (C): over C the load does not grow, so the run came to rest in contact; a
// window reaching back into A (a lighter press) read a growing load, `ended_in_contact`
TEST(HostMode, TheEndOfRunWindowsAreJudgedOverTheHostsTime) {
  Scenario s = LoadScenario(std::string(DYMESH_DATA_DIR) + "/scenarios/barrier_frontal.json");
  Simulation sim(s, BuildBodyModels(s), accel::MakeEmbreeLocatorFactory(std::make_shared<const accel::EmbreeDevice>()));
  ASSERT_TRUE(sim.placements().at(0).meet);
  const Vec3 into = sim.placements()[0].direction;
  std::vector<RigidState> states = {sim.engine().state(0).rigid, sim.engine().state(1).rigid};
  states[0].velocity.setZero();
  states[0].position += (sim.placements()[0].gap + 0.020) * into;
  const double dt = 0.002, press = 0.04;  // [s], [m/s]
  auto hold = [&](int steps, double speed) {
    states[0].velocity = speed * into;
    for (int k = 0; k < steps; ++k) {
      sim.HostStep(states, dt);
      states[0].position += speed * dt * into;
    }
  };
  hold(10, 0.0);    // A
  hold(20, press);  // B
  hold(15, 0.0);    // C
  sim.FinishHostRun(states);
  const Summary summary = Summarize(sim);
  EXPECT_FALSE(HasWarning(summary, "host_motion_inconsistent"));
  EXPECT_TRUE(sim.in_contact_at_end());
  EXPECT_EQ(summary.status, RunStatus::kComplete);
  EXPECT_TRUE(HasWarning(summary, "at_rest_in_contact"));
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
