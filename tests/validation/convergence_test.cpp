// Convergence and invariance of car-to-car collisions on real meshes (p406 and stock car): the
// shipped side-impact demo, a 45-degree oblique impact and an offset frontal, each against halving the
// time step, subdividing one mesh 1:4, turning the body frames by 10 degrees, and swapping body order.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "dymesh/io/body_models.h"
#include "dymesh/io/scenario_json.h"
#include "dymesh/accel/embree_locator.h"
#include "dymesh/analysis/summary.h"
#include "dymesh/core/simulation.h"

namespace dymesh {
namespace {

Scenario Demo(const std::string& name) { return LoadScenario(std::string(DYMESH_DATA_DIR) + "/scenarios/" + name); }

// what must not move: each body's delta-V, the contact work, and the energy balance
struct Outcome {
  std::vector<double> delta_v;  // [m/s] by body name order of the base scenario
  double crush = 0.0;           // [J] ledger crush work, all bodies
  double friction = 0.0;        // [J] ledger friction work, all bodies
  double balance = 0.0;
};

// the run; `swap` reverses the body order (results are mapped back to the base order)
Outcome Run(Scenario s, bool swap, std::vector<std::shared_ptr<const BodyModel>> models = {}) {
  if (swap) std::swap(s.bodies[0], s.bodies[1]);
  if (swap && !models.empty()) std::swap(models[0], models[1]);
  auto device = std::make_shared<const accel::EmbreeDevice>();
  if (models.empty()) models = BuildBodyModels(s);
  Simulation sim(s, models, accel::MakeEmbreeLocatorFactory(device));
  sim.Run();
  const Summary sum = Summarize(sim);
  Outcome o;
  o.delta_v = {sum.bodies[0].delta_v, sum.bodies[1].delta_v};
  if (swap) std::swap(o.delta_v[0], o.delta_v[1]);
  o.crush = sum.crush_energy;
  o.friction = sum.friction_energy;
  o.balance = sum.energy_balance_error;
  return o;
}

// a body-frame change: every mesh turned by `angle` about the body's vertical, the body turned back
// by the same angle, so the physical scene is unchanged (inertia turned with the mesh)
Outcome RunInTurnedBodyFrames(Scenario s, double angle) {
  const Mat3 turn = BodyToEarth(0.0, 0.0, angle);
  std::vector<std::shared_ptr<const BodyModel>> models;
  for (const auto& m : BuildBodyModels(s)) {
    TriMesh mesh = m->mesh;
    for (Vec3& p : mesh.vertices) p = turn * p;
    BodyModel turned = MakeBodyModel(m->name, std::move(mesh), m->stiffness, m->mass,
                                     turn * m->inertia * turn.transpose(), m->restitution, m->friction, m->rigid);
    // the same body described in another frame: each vertex keeps its surface (and stiffness), which
    // the body axes would otherwise reassign near the 45-degree borders between faces
    turned.surface = m->surface;
    models.push_back(std::make_shared<const BodyModel>(std::move(turned)));
  }
  for (BodySpec& b : s.bodies) b.initial.yaw -= angle;
  return Run(s, false, models);
}

// the bar: each variant changes delta-V and the contact work (crush + friction) by under 2 %,
// and balances within 2 %. The split of that work between crush and friction is printed, not held to
// 2 %: it moves by up to 3.7 % (offset, p406 mesh 1:4), a known limit in the README. (The oblique's
// delta-V missed the bar at dt/2, -2.92 %, until nodes pressed on a deformable master stopped
// unloading when a gap opened in front of them while the bodies still closed: now -1.78 %.)
void ExpectClose(const Outcome& base, const Outcome& v, const std::string& label) {
  for (size_t i = 0; i < base.delta_v.size(); ++i) {
    EXPECT_GT(base.delta_v[i], 1.0) << label;  // a real collision [m/s]
    EXPECT_NEAR(v.delta_v[i], base.delta_v[i], 0.02 * base.delta_v[i]) << label << " body " << i;
  }
  const double work = base.crush + base.friction;
  EXPECT_NEAR(v.crush + v.friction, work, 0.02 * work) << label;
  EXPECT_NEAR(v.balance, 0.0, 0.02) << label;
  std::printf("[measured] %s: delta-V %+.2f %% / %+.2f %%, contact work %+.2f %% (crush %+.2f %%, friction %+.2f %%)\n",
              label.c_str(), 100 * (v.delta_v[0] / base.delta_v[0] - 1), 100 * (v.delta_v[1] / base.delta_v[1] - 1),
              100 * ((v.crush + v.friction) / work - 1), 100 * (v.crush / base.crush - 1),
              100 * (v.friction / base.friction - 1));
}

void ExpectConverged(const std::string& name) {
  const Scenario base_scenario = Demo(name);
  const Outcome base = Run(base_scenario, false);
  Scenario half = base_scenario;
  half.time_step /= 2;
  ExpectClose(base, Run(half, false), name + " dt/2");
  Scenario fine = base_scenario;
  fine.bodies[0].mesh.subdivisions += 1;
  ExpectClose(base, Run(fine, false), name + " p406 mesh 1:4");
  ExpectClose(base, RunInTurnedBodyFrames(base_scenario, 10.0 * units::kDegree), name + " body frames +10 deg");
  // body order: bit-identical physics (the pair's passes run simultaneously), so exact equality
  const Outcome swapped = Run(base_scenario, true);
  EXPECT_EQ(swapped.delta_v, base.delta_v) << name;
  EXPECT_EQ(swapped.crush, base.crush) << name;
}

TEST(Convergence, SideImpactDemo) { ExpectConverged("car_to_car_side.json"); }
TEST(Convergence, Oblique45Degrees) { ExpectConverged("car_to_car_oblique.json"); }
TEST(Convergence, OffsetFrontal) { ExpectConverged("car_to_car_offset.json"); }

}  // namespace
}  // namespace dymesh
